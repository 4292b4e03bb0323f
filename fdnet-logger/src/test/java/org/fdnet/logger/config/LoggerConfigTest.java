package org.fdnet.logger.config;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class LoggerConfigTest {
    @TempDir
    Path folder;

    @Test
    void shouldHaveTheThesisDefaults() {
        LoggerConfig c = new LoggerConfig();
        assertThat(c.batchSize()).isEqualTo(1000);
        assertThat(c.batchTimeoutMillis()).isEqualTo(2000);
        assertThat(c.receiverPort()).isEqualTo(5555);
        assertThat(c.senderPort()).isEqualTo(5556);
        assertThat(c.criticalPercent()).isEqualTo(80);
        assertThat(c.normalPercent()).isEqualTo(50);
        assertThat(c.receiverAddress()).isEqualTo("127.0.0.1");
        assertThat(c.embeddedDatabase()).isTrue();
    }

    @Test
    void shouldGiveEverySettingAShortLabelAndAOneLineHelpForThePanel() {
        for (LoggerSetting s : LoggerSetting.values()) {
            assertThat(s.label()).as(s.key()).isNotBlank().hasSizeLessThanOrEqualTo(20);
            assertThat(s.help()).as(s.key()).isNotBlank().hasSizeLessThanOrEqualTo(55);
            assertThat(s.description()).as(s.key()).startsWith(s.help());
        }
    }

    @Test
    void shouldChangeOnlyLiveSettingsOnceSealed() {
        LoggerConfig c = new LoggerConfig();
        c.seal();
        c.setLive(LoggerSetting.WRITER_BATCH_TIMEOUT, "300");
        assertThat(c.batchTimeoutMillis()).isEqualTo(300);
        assertThatThrownBy(() -> c.setLive(LoggerSetting.WRITER_BATCH_TIMEOUT, "0"))
                .hasMessage("writer.batchTimeoutMillis must be in [1, 3600000], was 0");
        assertThatThrownBy(() -> c.setLive(LoggerSetting.WRITER_BATCH_SIZE, "10")).isInstanceOf(IllegalStateException.class);
        assertThatThrownBy(() -> LoggerConfig.check(LoggerSetting.RECEIVER_PORT, "port"))
                .hasMessage("receiver.port must be a whole number, was 'port'");
    }

    @Test
    void shouldRejectBadValuesWithPreciseMessages() {
        LoggerConfig c = new LoggerConfig();
        assertThatThrownBy(() -> c.set(LoggerSetting.WRITER_BATCH_SIZE, "0"))
                .hasMessage("writer.batchSize must be in [1, 1000000], was 0");
        assertThatThrownBy(() -> c.set(LoggerSetting.RECEIVER_PORT, "70000"))
                .hasMessage("receiver.port must be in [0, 65535], was 70000");
        assertThatThrownBy(() -> c.set(LoggerSetting.PRIORITY_ENABLED, "yes"))
                .hasMessage("priority.enabled must be true or false, was 'yes'");
        assertThatThrownBy(() -> c.set(LoggerSetting.DATABASE_URL, "jdbc:mysql://x"))
                .hasMessageContaining("must start with jdbc:postgresql:");
        c.set(LoggerSetting.PRIORITY_NORMAL, "90");
        assertThatThrownBy(c::validate).hasMessage("priority.normalPercent must be below priority.criticalPercent (80), was 90");
    }

    @Test
    void shouldBeSealedOnceStarted() {
        LoggerConfig c = new LoggerConfig();
        c.seal();
        assertThatThrownBy(() -> c.set(LoggerSetting.WRITER_BATCH_SIZE, "5")).isInstanceOf(IllegalStateException.class)
                .hasMessageContaining("sealed");
    }

    @Test
    void shouldSaveAndLoadEveryParameterAndNameTheFileOfABadOne() throws Exception {
        Path file = folder.resolve("logger.properties");
        LoggerConfig c = new LoggerConfig().set(LoggerSetting.WRITER_BATCH_SIZE, "250")
                .set(LoggerSetting.PRIORITY_CRITICAL, "40").set(LoggerSetting.PRIORITY_NORMAL, "20");
        LoggerConfigFile.save(c, file);
        LoggerConfig back = LoggerConfigFile.load(file);
        for (LoggerSetting s : LoggerSetting.values()) {
            assertThat(back.get(s)).as(s.key()).isEqualTo(c.get(s));
        }
        Files.writeString(file, "writer.batchTimeoutMillis=-5\n");
        assertThatThrownBy(() -> LoggerConfigFile.load(file)).hasMessageContaining(file.toString())
                .hasMessageContaining("writer.batchTimeoutMillis must be in [1, 3600000], was -5");
    }
}
