package org.fdnet.testkit;

import java.lang.annotation.Documented;
import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;
import org.junit.jupiter.api.extension.ExtendWith;

/**
 * Marks a test class whose test methods take {@link TestNetwork} parameters annotated with {@link NetworkFile}: each
 * gets the network started on a driven clock before the method and closed after it.
 *
 * <pre>{@code
 * @FdnetTest
 * class GainTest {
 *     @Test
 *     void shouldDoubleItsInput(@NetworkFile("networks/lab.fdn") TestNetwork net) {
 *         net.set("Lab/input", 0.5);
 *         net.advance(Duration.ofMillis(20));
 *         net.assertValue("Lab/output").isCloseTo(1.0, 1e-9);
 *     }
 * }
 * }</pre>
 */
@Documented
@Retention(RetentionPolicy.RUNTIME)
@Target(ElementType.TYPE)
@ExtendWith(FdnetExtension.class)
public @interface FdnetTest {
}
