package org.fdnet.logger.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.BufferedReader;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.io.StringReader;
import java.nio.charset.StandardCharsets;
import org.fdnet.logger.NetworkStateLogger;
import org.fdnet.logger.config.LoggerConfig;
import org.junit.jupiter.api.Test;

/** The prompt's answers that need no database (retry against a real one: FaultToleranceTest). */
class LoggerPromptTest {
    @Test
    void shouldAnswerHelpAndUnknownCommandsWithTheListAndEndWithItsInput() {
        ByteArrayOutputStream answers = new ByteArrayOutputStream();
        NetworkStateLogger notStarted = new NetworkStateLogger(new LoggerConfig());
        new LoggerPrompt(notStarted, new BufferedReader(new StringReader("help\n\n  STATUS \nfrobnicate\n")),
                new PrintStream(answers, true, StandardCharsets.UTF_8)).run();
        assertThat(answers.toString(StandardCharsets.UTF_8).lines()).containsExactly(LoggerPrompt.HELP,
                "fdnet logger: not running", "fdnet logger: unknown command 'frobnicate'; " + LoggerPrompt.HELP);
    }
}
