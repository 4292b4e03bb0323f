package org.fdnet.runtime.library;

import static org.assertj.core.api.Assertions.assertThat;

import com.code_intelligence.jazzer.junit.FuzzTest;
import java.nio.charset.StandardCharsets;

/**
 * Fuzzes the {@link Expression} Relation's language ({@link ExpressionParser}): any text either compiles or is
 * refused with an {@link IllegalArgumentException} that names the column; a compiled expression evaluates to a
 * vector or fails with an {@link IllegalArgumentException} that says what (an index outside a vector, vectors of
 * different lengths) — never an unchecked crash, a stack overflow or a hang. Seeds and kept findings:
 * {@code src/test/resources/org/fdnet/runtime/library/ExpressionFuzzTestInputs/}.
 */
class ExpressionFuzzTest {

    /** Inputs as a Relation with four inputs sees them: vectors of 1 to 4 numbers; any other name is missing. */
    private static final ExpressionParser.Env INPUTS = name -> switch (name) {
        case "in0", "x" -> new double[] {0.5};
        case "in1" -> new double[] {1, -2};
        case "in2" -> new double[] {3, 0, -1};
        case "in3", "posture" -> new double[] {0.1, 0.2, 0.3, 0.4};
        case "t" -> new double[] {2.5};
        default -> throw new MissingInput(name);
    };

    @FuzzTest(maxDuration = "10m")
    void shouldCompileOrNameTheColumn(byte[] input) {
        String text = new String(input, StandardCharsets.UTF_8);
        ExpressionParser.Node compiled;
        try {
            compiled = ExpressionParser.parse(text);
        } catch (IllegalArgumentException refused) {
            assertThat(refused).isExactlyInstanceOf(IllegalArgumentException.class);
            assertThat(refused.getMessage()).contains("column");
            return;
        }
        assertThat(ExpressionParser.names(text)).isNotNull();
        try {
            double[] result = compiled.eval(INPUTS);
            assertThat(result).isNotNull();
        } catch (MissingInput missing) {
            assertThat(missing.getMessage()).isNotEmpty();
        } catch (IllegalArgumentException failed) {
            assertThat(failed).isExactlyInstanceOf(IllegalArgumentException.class);
            assertThat(failed.getMessage()).isNotBlank();
        }
    }
}
