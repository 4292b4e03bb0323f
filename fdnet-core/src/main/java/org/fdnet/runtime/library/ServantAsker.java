package org.fdnet.runtime.library;

import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.Controller;
import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.ParameterSpec;
import org.fdnet.runtime.Relation;
import org.fdnet.runtime.RelationContext;
import org.fdnet.runtime.ReturnListener;
import org.fdnet.runtime.Value;

/**
 * A Relation that asks a servant (thesis Appendix 2, {@code sendMessage} with a {@code ReturnListener}): each time
 * its first input changes it sends message {@code message} (default {@code evaluate}) with that value to the
 * servant at path {@code servant}, on this host or any other, and goes on; when the reply comes back, it is written
 * to every output Data. A refusal (no such servant, not loaded yet, refused) is reported as the Relation's status
 * at its next firing; the outputs keep their values.
 */
public class ServantAsker extends Relation {
    public static final ParameterSpec<String> SERVANT = ParameterSpec.text("servant")
            .describe("the path of the servant asked").live();
    public static final ParameterSpec<String> MESSAGE = ParameterSpec.text("message").defaultValue("evaluate")
            .describe("the message sent").live();

    private String path;
    private String message;
    private final AtomicReference<String> lastRefusal = new AtomicReference<>();
    private final AtomicLong replies = new AtomicLong();

    @Override
    protected void init(NodeParameters parameters) {
        path = SERVANT.read(parameters).strip();
        message = MESSAGE.read(parameters).strip();
    }

    @Override
    protected void compute(RelationContext context) {
        String refusal = lastRefusal.getAndSet(null);
        if (refusal != null) {
            context.report("refused: " + refusal);
        } else if (replies.get() > 0) {
            context.report("RUNNING");
        }
        Value asked = context.inputCount() == 0 ? null : context.input(0);
        if (asked == null || !context.inputChanged(0)) {
            return;
        }
        Controller controller = context.servants().controller();
        NodeRef[] outputs = new NodeRef[context.outputCount()];
        for (int i = 0; i < outputs.length; i++) {
            outputs[i] = context.outputRef(i);
        }
        context.servants().sendMessage(path, message, asked, ReturnListener.of(reply -> {
            replies.incrementAndGet();
            for (NodeRef out : outputs) {
                controller.setValue(out, reply);
            }
        }, lastRefusal::set));
    }
}
