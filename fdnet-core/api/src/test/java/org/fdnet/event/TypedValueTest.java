package org.fdnet.event;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.List;
import org.junit.jupiter.api.Test;

class TypedValueTest {
    private static final List<TypedValue> EVERY_TYPE = List.of(
            TypedValue.of(true), TypedValue.of(-7L), TypedValue.of(0.1 + 0.2), TypedValue.of("a,b\tc"),
            TypedValue.ofBytes(new byte[] {0, 1, -2}), TypedValue.ofDoubles(0.5, -1.0E-9, 3.0));

    @Test
    void shouldReadItsTextBackAsTheSameValue() {
        for (TypedValue v : EVERY_TYPE) {
            assertThat(TypedValue.parse(v.type(), v.text())).as(v.text()).isEqualTo(v);
        }
        assertThat(TypedValue.of(0.1 + 0.2).text()).isEqualTo(Double.toString(0.1 + 0.2));
        assertThat(TypedValue.ofDoubles(0.5, 2.0).text()).isEqualTo("0.5,2.0");
    }

    @Test
    void shouldHoldNumbersExactlyWithoutText() {
        assertThat(TypedValue.of(Long.MAX_VALUE).longValue()).isEqualTo(Long.MAX_VALUE);
        assertThat(TypedValue.of(Long.MAX_VALUE).isNumber()).isTrue();
        assertThat(TypedValue.of(0.25).number()).isEqualTo(0.25);
        assertThat(TypedValue.of(Double.NaN)).isEqualTo(TypedValue.of(Double.longBitsToDouble(0x7ff8000000000001L)));
        assertThat(TypedValue.of(0.0)).isNotEqualTo(TypedValue.of(-0.0));
        assertThat(TypedValue.of(true).isNumber()).isFalse();
    }

    @Test
    void shouldKeepItsArraysToItself() {
        double[] posture = {1, 2};
        TypedValue v = TypedValue.ofDoubles(posture);
        posture[0] = 99;
        v.doubles()[1] = 99;
        assertThat(v).isEqualTo(TypedValue.ofDoubles(1, 2));
    }

    @Test
    void shouldRefuseAReadOfTheWrongTypeNamingBoth() {
        assertThatThrownBy(() -> TypedValue.of("x").doubleValue()).isInstanceOf(IllegalStateException.class)
                .hasMessage("a STRING value read as DOUBLE");
        assertThatThrownBy(() -> TypedValue.parse(ValueType.LONG, "4.5")).isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("'4.5'");
    }
}
