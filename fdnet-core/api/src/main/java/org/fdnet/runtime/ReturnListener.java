package org.fdnet.runtime;

import java.util.function.Consumer;

/**
 * The thesis's {@code ReturnListener}: how a servant tells the Relation that sent it a message that its work is
 * done. Called once per message, on a messaging thread of the sender's engine (never inside the sender's firing):
 * keep it short and thread-safe, e.g. write the reply into a Data with {@code servants.controller().setValue}.
 */
public interface ReturnListener {
    /**
     * The servant answered.
     *
     * @param reply the servant's reply
     */
    void returned(Value reply);

    /**
     * No servant answered: none at that path on any host, or it refused; {@code reason} says which.
     *
     * @param reason why, naming the path or the servant
     */
    void refused(String reason);

    /**
     * A listener of two lambdas.
     *
     * @param returned called with the reply
     * @param refused  called with the reason there is none
     * @return a listener that calls one of them
     */
    static ReturnListener of(Consumer<Value> returned, Consumer<String> refused) {
        return new ReturnListener() {
            @Override
            public void returned(Value reply) {
                returned.accept(reply);
            }

            @Override
            public void refused(String reason) {
                refused.accept(reason);
            }
        };
    }
}
