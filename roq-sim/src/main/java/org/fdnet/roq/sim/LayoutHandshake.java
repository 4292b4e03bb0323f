package org.fdnet.roq.sim;

import java.lang.reflect.Field;
import java.lang.reflect.Modifier;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Compares the native side's one table of shared figures ({@code ROQ_LAYOUT} in {@code src/main/c/roq_layout.h},
 * exported as names and values) with every {@code int} and {@code long} constant of {@link SharedBlockLayout} and
 * {@link NativeParameters}, by name: a figure that differs, or that one side has and the other lacks, is named.
 * Neither side keeps a list of the fields to compare, so a field added to one side only is caught as well.
 * A native name's leading {@code ROQ_} is not part of the name ({@code ROQ_BLOCK_SIZE} is
 * {@link SharedBlockLayout#BLOCK_SIZE}).
 */
final class LayoutHandshake {
    private static final String NATIVE_PREFIX = "ROQ_";
    private static final List<Class<?>> JAVA_SIDE = List.of(SharedBlockLayout.class, NativeParameters.class);

    private LayoutHandshake() {
    }

    /**
     * Every disagreement between the native table and the Java constants, one line each ("S_GYRO: Java 3664, native
     * 3672"); empty when they agree.
     *
     * @throws IllegalArgumentException when the two native arrays differ in length
     */
    static List<String> mismatches(String[] nativeNames, long[] nativeValues) {
        return mismatches(nativeNames, nativeValues, javaConstants());
    }

    static List<String> mismatches(String[] nativeNames, long[] nativeValues, Map<String, Long> java) {
        if (nativeNames.length != nativeValues.length) {
            throw new IllegalArgumentException("the native layout table has " + nativeNames.length + " names but "
                    + nativeValues.length + " values");
        }
        Map<String, Long> remaining = new LinkedHashMap<>(java);
        List<String> problems = new ArrayList<>();
        for (int i = 0; i < nativeNames.length; i++) {
            String name = nativeNames[i].startsWith(NATIVE_PREFIX)
                    ? nativeNames[i].substring(NATIVE_PREFIX.length()) : nativeNames[i];
            Long javaValue = remaining.remove(name);
            if (javaValue == null) {
                problems.add(name + ": native " + nativeValues[i] + ", no such constant in Java");
            } else if (javaValue != nativeValues[i]) {
                problems.add(name + ": Java " + javaValue + ", native " + nativeValues[i]);
            }
        }
        remaining.forEach((name, value) -> problems.add(name + ": Java " + value + ", not in the native layout"));
        return problems;
    }

    /** Every static final int and long of the Java side, by name, in declaration order. */
    static Map<String, Long> javaConstants() {
        Map<String, Long> constants = new LinkedHashMap<>();
        for (Class<?> owner : JAVA_SIDE) {
            for (Field field : owner.getDeclaredFields()) {
                int modifiers = field.getModifiers();
                Class<?> type = field.getType();
                if (!Modifier.isStatic(modifiers) || !Modifier.isFinal(modifiers)
                        || (type != int.class && type != long.class)) {
                    continue;
                }
                Long previous = constants.put(field.getName(), read(field));
                if (previous != null) {
                    throw new IllegalStateException("roq-sim: constant " + field.getName() + " is declared twice on "
                            + "the Java side of the layout (" + JAVA_SIDE + ")");
                }
            }
        }
        return constants;
    }

    private static long read(Field field) {
        try {
            field.setAccessible(true);
            return field.getType() == int.class ? field.getInt(null) : field.getLong(null);
        } catch (IllegalAccessException e) {
            throw new IllegalStateException("roq-sim: cannot read layout constant " + field, e);
        }
    }
}
