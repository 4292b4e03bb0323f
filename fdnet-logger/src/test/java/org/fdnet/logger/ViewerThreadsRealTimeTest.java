package org.fdnet.logger;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.fdnet.event.client.ViewerClient;
import org.fdnet.logger.config.LoggerSetting;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.RegisterExtension;

/**
 * The threads a waiting viewer depends on — the logger's sender thread for its connection and the viewer's
 * reader — run real-time (SCHED_FIFO) where the process may have it (root, as in CI); with
 * {@code priority.enabled=false} the logger's stays a normal thread. Read from /proc, by thread name.
 */
@Timeout(value = 120, unit = TimeUnit.SECONDS)
class ViewerThreadsRealTimeTest {
    private static final String SCHED_FIFO = "1";
    private static final String SCHED_OTHER = "0";

    @RegisterExtension
    static final PostgresPerClass database = new PostgresPerClass();

    @Test
    void shouldAnswerAViewerFromRealTimeThreadsWherePermitted() throws Exception {
        String expected = isRoot() ? SCHED_FIFO : SCHED_OTHER;
        try (NetworkStateLogger logger = new NetworkStateLogger(database.fixture().loggerConfig())) {
            logger.start();
            try (ViewerClient viewer = new ViewerClient("127.0.0.1", logger.senderPort(), "rt-viewer", e -> { })) {
                viewer.nodes(""); // a round trip: both threads have started serving
                assertThat(policiesOf("sender-/127.0.0")).as("the logger's sender thread").containsExactly(expected);
                assertThat(policiesOf("fdnet-viewer-cl")).as("the viewer's reader").containsExactly(expected);
            }
        }
    }

    @Test
    void shouldLeaveTheSenderThreadNormalWithPriorityDisabled() throws Exception {
        try (NetworkStateLogger logger = new NetworkStateLogger(database.fixture().loggerConfig()
                .set(LoggerSetting.PRIORITY_ENABLED, "false"))) {
            logger.start();
            try (ViewerClient viewer = new ViewerClient("127.0.0.1", logger.senderPort(), "normal-viewer", e -> { })) {
                viewer.nodes("");
                assertThat(policiesOf("sender-/127.0.0")).containsExactly(SCHED_OTHER);
            }
        }
    }

    /** The scheduling policy (field 41 of stat) of every thread of this process whose name starts so. */
    private static List<String> policiesOf(String namePrefix) throws IOException {
        List<String> policies = new ArrayList<>();
        try (Stream<Path> tasks = Files.list(Path.of("/proc/self/task"))) {
            for (Path task : (Iterable<Path>) tasks::iterator) {
                String stat;
                try {
                    stat = Files.readString(task.resolve("stat"));
                } catch (IOException gone) {
                    continue; // the thread ended meanwhile
                }
                String name = stat.substring(stat.indexOf('(') + 1, stat.lastIndexOf(')'));
                if (name.startsWith(namePrefix)) {
                    policies.add(stat.substring(stat.lastIndexOf(')') + 2).split(" ")[41 - 3]);
                }
            }
        }
        return policies;
    }

    private static boolean isRoot() throws IOException {
        for (String line : Files.readAllLines(Path.of("/proc/self/status"))) {
            if (line.startsWith("Uid:")) {
                return line.split("\\s+")[2].equals("0");
            }
        }
        throw new IllegalStateException("no Uid: line in /proc/self/status");
    }
}
