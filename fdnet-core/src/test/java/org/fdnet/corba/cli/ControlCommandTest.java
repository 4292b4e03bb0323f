package org.fdnet.corba.cli;

import static org.assertj.core.api.Assertions.assertThat;

import org.fdnet.corba.FdnetChildProcess;
import org.fdnet.runtime.Value;
import org.fdnet.testing.CliRun;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

@Timeout(60)
class ControlCommandTest {
    @Test
    void shouldTakeTheParameterAfterTheColonAsRunsStandardInputDoes() {
        assertThat(ControlCommand.parameterAssignment("Balance/keep balance:margin=0.08"))
                .isEqualTo("Balance/keep balance/margin=0.08");
        assertThat(ControlCommand.parameterAssignment("Gain/expression=2 * in0")).isEqualTo("Gain/expression=2 * in0");
        assertThat(ControlCommand.parameterAssignment("Gain:expression=a:b")).isEqualTo("Gain/expression=a:b");
    }

    @Test
    void shouldShowNumbersShortAndVectorsByTheirFirstValues() {
        assertThat(ControlCommand.shortText(Value.of(0.123456789))).isEqualTo("0.1235");
        assertThat(ControlCommand.shortText(Value.ofDoubles(1, 2, 3, 4, 5))).isEqualTo("[1.00, 2.00, 3.00, … 5 values]");
        assertThat(ControlCommand.shortText(Value.of(true))).isEqualTo("true");
    }

    @Test
    void shouldSayNoNetworkAnswersAtAnAddressWhereNoneRuns() {
        int port = FdnetChildProcess.freePort();
        CliRun cli = new CliRun();

        int exit = cli.fdnet("control", "127.0.0.1:" + port, "status");

        assertThat(exit).isEqualTo(1);
        assertThat(cli.output()).contains("no running network answers at corbaloc::127.0.0.1:" + port + "/FDNetControl");
    }
}
