package org.fdnet.runtime;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.List;
import org.fdnet.event.ValueType;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;
import org.fdnet.netinfo.ValueRange;
import org.fdnet.runtime.library.PeriodicSource;
import org.fdnet.runtime.library.Threshold;
import org.junit.jupiter.api.Test;

class ParameterSpecTest {
    private static final ParameterSpec<Double> GAIN = ParameterSpec.number("gain").unit("m").range(0, 10)
            .defaultValue(1.0).describe("how much").live();

    private static NodeParameters given(String... pairs) {
        Parameter[] ps = TestNetworks.parameters(pairs);
        return new NodeParameters(new NodeRef("Arm", "Amp"), List.of(ps));
    }

    @Test
    void shouldReadTheDefaultWhenTheParameterIsAbsent() {
        assertThat(GAIN.read(given())).isEqualTo(1.0);
        assertThat(GAIN.read(given("gain=2.5"))).isEqualTo(2.5);
    }

    @Test
    void shouldRefuseAValueOutsideTheRangeNamingModuleNodeParameterAndRange() {
        assertThatThrownBy(() -> GAIN.read(given("gain=12")))
                .isInstanceOf(ParameterException.class)
                .hasMessage("module 'Arm', node 'Amp': parameter 'gain' must be a number in [0, 10] m, was 12");
        assertThatThrownBy(() -> GAIN.read(given("gain=fast")))
                .hasMessage("module 'Arm', node 'Amp': parameter 'gain' must be a number in [0, 10] m, was 'fast'");
    }

    @Test
    void shouldNotWriteTheUnitOfARatioAfterItsRange() {
        ParameterSpec<Double> ratio = ParameterSpec.number("ratio").unit("1").range(0, 10);
        assertThatThrownBy(() -> ratio.read(given("ratio=12")))
                .hasMessageEndingWith("parameter 'ratio' must be a number in [0, 10], was 12");
    }

    @Test
    void shouldRefuseAMissingRequiredParameterSayingWhatItMustBe() {
        ParameterSpec<Long> window = ParameterSpec.whole("window").atLeast(1);
        assertThatThrownBy(() -> window.read(given()))
                .hasMessage("module 'Arm', node 'Amp': parameter 'window' is required: it must be a whole number at least 1");
    }

    @Test
    void shouldAcceptTheOffValueOutsideTheRange() {
        ParameterSpec<Double> bias = ParameterSpec.number("biasTime").unit("s").range(1, 1000).or(0.0).defaultValue(20.0);
        assertThat(bias.read(given("biasTime=0"))).isEqualTo(0.0);
        assertThatThrownBy(() -> bias.read(given("biasTime=0.5")))
                .hasMessageEndingWith("parameter 'biasTime' must be 0 or a number in [1, 1000] s, was 0.5");
    }

    @Test
    void shouldCheckEveryNumberOfAList() {
        ParameterSpec<double[]> weights = ParameterSpec.numbers("weights").atLeast(0).optional();
        assertThat(weights.read(given("weights=1, 0.5"))).containsExactly(1.0, 0.5);
        assertThat(weights.read(given())).isNull();
        assertThatThrownBy(() -> weights.read(given("weights=1 -2"))).hasMessageContaining("each at least 0, was 1, -2");
    }

    @Test
    void shouldReadAnEnumChoiceInAnyCaseAndListTheChoicesWhenRefused() {
        ParameterSpec<ValueType> type = ParameterSpec.choice("type", ValueType.class);
        assertThat(type.read(given("type=Double"))).isEqualTo(ValueType.DOUBLE);
        assertThatThrownBy(() -> type.read(given("type=complex")))
                .hasMessageContaining("parameter 'type' must be one of ").hasMessageContaining("double")
                .hasMessageEndingWith("was 'complex'");
    }

    @Test
    void shouldGiveTheParsersReasonWhenParsedTextIsRefused() {
        ParameterSpec<Integer> even = ParameterSpec.parsed("even", "an even number", t -> {
            int n = Integer.parseInt(t.strip());
            if (n % 2 != 0) {
                throw new IllegalArgumentException(n + " is odd");
            }
            return n;
        });
        assertThatThrownBy(() -> even.read(given("even=3")))
                .hasMessageEndingWith("parameter 'even' must be an even number, was '3': 3 is odd");
    }

    @Test
    void shouldLeaveTheDeclarationUnchangedWhenANewOneIsShapedFromIt() {
        ParameterSpec<Double> narrower = GAIN.range(0, 1);
        assertThat(GAIN.range()).isEqualTo(ValueRange.closed(0, 10));
        assertThat(narrower.range()).isEqualTo(ValueRange.closed(0, 1));
        assertThat(narrower.isLive()).isTrue();
    }

    @Test
    void shouldRefuseARangeOnText() {
        assertThatThrownBy(() -> ParameterSpec.text("name").range(0, 1)).isInstanceOf(IllegalStateException.class);
    }

    @Test
    void shouldNameBothParametersAndTheirValuesInAConflict() {
        NodeParameters p = given("low=3", "high=2");
        assertThat(p.conflict(Threshold.LOW, Threshold.HIGH, "low must not be above high"))
                .hasMessage("module 'Arm', node 'Amp': parameters 'low' (3) and 'high' (2) do not fit together:"
                        + " low must not be above high");
    }

    @Test
    void shouldFindTheClassOwnDeclarationsFirstThenTheEnginesOnes() {
        List<String> names = DeclaredParameters.of(Threshold.class).all().stream().map(ParameterSpec::name).toList();
        assertThat(names).containsExactly("high", "low", "absolute", "period", "onInput", "triggers");
    }

    @Test
    void shouldLetAClassNarrowAnInheritedDeclaration() {
        DeclaredParameters declared = DeclaredParameters.of(PeriodicSource.class);
        assertThat(declared.find("period").isRequired()).isTrue();
        assertThatThrownBy(() -> declared.check(given("waveform=sine")))
                .hasMessageContaining("parameter 'period' is required: it must be a whole number above 0 ms");
    }

    @Test
    void shouldListTheNamedParametersAClassDoesNotDeclare() {
        assertThat(DeclaredParameters.of(Threshold.class).undeclared(given("high=1", "hihg=2"))).containsExactly("hihg");
    }

    @Test
    void shouldWordARangeAsAUserReadsIt() {
        assertThat(ValueRange.closed(0, 0.3).phrase("m")).isEqualTo("in [0, 0.3] m");
        assertThat(ValueRange.ANY.withMin(0, false).withMax(1, true).phrase("")).isEqualTo("in (0, 1]");
        assertThat(ValueRange.ANY.withMin(1, true).phrase("s")).isEqualTo("at least 1 s");
        assertThat(ValueRange.ANY.withMax(20, false).phrase("")).isEqualTo("below 20");
        assertThatThrownBy(() -> ValueRange.closed(1, 1_000_000).check("writer.batchSize", 0, ""))
                .hasMessage("writer.batchSize must be in [1, 1000000], was 0");
    }
}
