package org.fdnet.roq.testkit;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.extension.ExtensionContext;
import org.junit.jupiter.api.extension.ParameterContext;
import org.junit.jupiter.api.extension.ParameterResolutionException;
import org.junit.jupiter.api.extension.ParameterResolver;
import org.junit.jupiter.api.extension.TestExecutionExceptionHandler;

/**
 * Starts the {@link SimulatedRoq} a {@link Roq}-annotated parameter asks for, closes it after the test, and when the
 * test method throws, writes the run's evidence ({@link FailureEvidence}) and rethrows the failure with the picture's
 * path and the replay command added to its message. Registered by {@link RoqTest}.
 */
public final class RoqExtension implements ParameterResolver, TestExecutionExceptionHandler {
    private static final ExtensionContext.Namespace NAMESPACE = ExtensionContext.Namespace.create(RoqExtension.class);
    private static final String RUNS = "runs";

    @Override
    public boolean supportsParameter(ParameterContext parameter, ExtensionContext context) {
        return parameter.getParameter().getType() == SimulatedRoq.class && parameter.isAnnotated(Roq.class);
    }

    @Override
    public Object resolveParameter(ParameterContext parameter, ExtensionContext context) {
        Roq spec = parameter.findAnnotation(Roq.class).orElseThrow();
        SimulatedRoq roq;
        try {
            SimulatedRoq.Builder builder = SimulatedRoq.builder().network(Path.of(spec.network())).course(spec.course())
                    .noise(spec.noise()).unload(spec.unload());
            roq = (spec.sensorNoise() ? builder : builder.withoutNoise()).start();
        } catch (RuntimeException e) {
            throw new ParameterResolutionException("@Roq(network = \"" + spec.network() + "\", course = \""
                    + spec.course() + "\") of " + parameter.getDeclaringExecutable().getName() + ": " + e.getMessage(), e);
        }
        context.getStore(NAMESPACE).put(parameter.getIndex(), (ExtensionContext.Store.CloseableResource) roq::close);
        runs(context).add(roq);
        return roq;
    }

    @Override
    public void handleTestExecutionException(ExtensionContext context, Throwable failure) throws Throwable {
        List<SimulatedRoq> runs = runs(context);
        if (runs.isEmpty()) {
            throw failure;
        }
        StringBuilder evidence = new StringBuilder();
        String stem = context.getRequiredTestClass().getSimpleName() + "." + context.getRequiredTestMethod().getName();
        for (int i = 0; i < runs.size(); i++) {
            evidence.append(FailureEvidence.write(runs.get(i), runs.size() == 1 ? stem : stem + "-" + (i + 1)));
        }
        AssertionError withEvidence = new AssertionError(failure.getMessage() + evidence, failure);
        withEvidence.setStackTrace(failure.getStackTrace());
        throw withEvidence;
    }

    @SuppressWarnings("unchecked")
    private static List<SimulatedRoq> runs(ExtensionContext context) {
        return context.getStore(NAMESPACE).getOrComputeIfAbsent(RUNS, key -> new ArrayList<SimulatedRoq>(), List.class);
    }
}
