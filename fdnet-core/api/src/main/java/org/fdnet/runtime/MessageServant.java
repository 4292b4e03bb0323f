package org.fdnet.runtime;

/**
 * What a servant of the servant tree does with a message (thesis Appendix 2, {@code sendMessage}): answers
 * {@code message} with {@code argument} by a reply, both FDNet values, so a message crosses hosts as any Data value
 * does. One servant answers one message at a time; a servant that cannot answer throws
 * {@link MessageRefusedException} with the reason, which the sender's {@link ReturnListener} receives.
 */
@FunctionalInterface
public interface MessageServant {
    /**
     * Answers one message; called on a messaging thread, never for two messages at once.
     *
     * @param message  what to do, e.g. {@code plan}
     * @param argument the sender's argument
     * @return the reply, any FDNet value
     * @throws MessageRefusedException when it cannot answer, saying why (any other exception is refused too)
     */
    Value answer(String message, Value argument);
}
