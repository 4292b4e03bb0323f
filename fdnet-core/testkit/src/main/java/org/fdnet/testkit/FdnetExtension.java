package org.fdnet.testkit;

import java.nio.file.Path;
import org.junit.jupiter.api.extension.ExtensionContext;
import org.junit.jupiter.api.extension.ParameterContext;
import org.junit.jupiter.api.extension.ParameterResolutionException;
import org.junit.jupiter.api.extension.ParameterResolver;

/**
 * Resolves {@link TestNetwork} parameters annotated with {@link NetworkFile}: starts the network before the test
 * method and closes it after, whatever the outcome. Registered by {@link FdnetTest}.
 */
public final class FdnetExtension implements ParameterResolver {
    private static final ExtensionContext.Namespace NAMESPACE = ExtensionContext.Namespace.create(FdnetExtension.class);

    @Override
    public boolean supportsParameter(ParameterContext parameter, ExtensionContext context) {
        return parameter.getParameter().getType() == TestNetwork.class && parameter.isAnnotated(NetworkFile.class);
    }

    @Override
    public Object resolveParameter(ParameterContext parameter, ExtensionContext context) {
        String file = parameter.findAnnotation(NetworkFile.class).orElseThrow().value();
        TestNetwork network;
        try {
            network = TestNetwork.start(Path.of(file));
        } catch (RuntimeException e) {
            throw new ParameterResolutionException("@NetworkFile(\"" + file + "\") of "
                    + parameter.getDeclaringExecutable().getName() + ": " + e.getMessage(), e);
        }
        context.getStore(NAMESPACE).put(parameter.getIndex(), (ExtensionContext.Store.CloseableResource) network::close);
        return network;
    }
}
