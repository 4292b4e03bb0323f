package org.fdnet.roq.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/** The built library's one layout table agrees with Java's constants, and a field moved on one side is named. */
class LayoutHandshakeTest {
    private static String[] names;
    private static long[] values;

    @BeforeAll
    static void loadTheNativeTable() {
        RoqNativeLibrary.ensureLoaded();
        names = RoqNative.layoutNames();
        values = RoqNative.layoutValues();
    }

    @Test
    void shouldAgreeOnEveryFieldOfTheBuiltLibrary() {
        assertThat(LayoutHandshake.mismatches(names, values)).isEmpty();
        assertThat(names).as("every Java constant has its native entry")
                .hasSize(LayoutHandshake.javaConstants().size());
        assertThat(names).contains("S_GYRO", "ROQ_BLOCK_SIZE", "P_CAMERA_0", "F_STRENGTH", "X_KIND_BREAK");
    }

    @Test
    void shouldNameAFieldMovedOnTheNativeSide() {
        long[] moved = values.clone();
        moved[Arrays.asList(names).indexOf("S_GYRO")] += 8;
        int gyro = SharedBlockLayout.S_GYRO;
        assertThat(LayoutHandshake.mismatches(names, moved))
                .containsExactly("S_GYRO: Java " + gyro + ", native " + (gyro + 8));
    }

    @Test
    void shouldNameAFieldOnlyOneSideHas() {
        Map<String, Long> java = new LinkedHashMap<>(LayoutHandshake.javaConstants());
        java.put("S_NEW_SENSOR", 3800L);
        java.remove("P_NOISE_SEED");
        List<String> problems = LayoutHandshake.mismatches(names, values, java);
        assertThat(problems).containsExactlyInAnyOrder("P_NOISE_SEED: native " + NativeParameters.P_NOISE_SEED
                + ", no such constant in Java", "S_NEW_SENSOR: Java 3800, not in the native layout");
    }

    @Test
    void shouldRefuseATableWhoseNamesAndValuesDiffer() {
        assertThatThrownBy(() -> LayoutHandshake.mismatches(names, Arrays.copyOf(values, values.length - 1)))
                .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("names but");
    }
}
