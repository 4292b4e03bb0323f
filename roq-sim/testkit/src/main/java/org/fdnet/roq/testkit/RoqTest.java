package org.fdnet.roq.testkit;

import java.lang.annotation.Documented;
import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;
import org.fdnet.testkit.FdnetExtension;
import org.junit.jupiter.api.extension.ExtendWith;

/**
 * Marks a test class whose test methods take {@link SimulatedRoq} parameters annotated with {@link Roq} (and, as
 * with {@code @FdnetTest}, {@code TestNetwork} parameters annotated with {@code @NetworkFile}). Each robot is started
 * before its method and closed after it; a method that fails leaves its run recorded for
 * {@code fdnet viewer --replay} and a picture of the robot view, both named in the failure message.
 *
 * <pre>{@code
 * @RoqTest
 * class CrossingTest {
 *     @Test
 *     void shouldCrossRubbleSeed12WithoutAFall(
 *             @Roq(network = "networks/lab-rubble.fdn", course = "rubble:12", noise = 7) SimulatedRoq roq) {
 *         roq.runFor(Duration.ofSeconds(40));
 *         roq.assertThat().noFall().walkedAtLeast(0.8).trackErrorAtMost(0.3).noLoadedFootBreakthrough();
 *     }
 * }
 * }</pre>
 */
@Documented
@Retention(RetentionPolicy.RUNTIME)
@Target(ElementType.TYPE)
@ExtendWith({RoqExtension.class, FdnetExtension.class})
public @interface RoqTest {
}
