package org.fdnet.netinfo.xml;

import static org.assertj.core.api.Assertions.assertThat;

import com.code_intelligence.jazzer.junit.FuzzTest;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Arrays;
import org.fdnet.layout.NetworkLayout;
import org.fdnet.netinfo.NetworkInfo;

/**
 * Fuzzes the network repository's readers: the first byte picks the {@code .fdn} reader (even) or the {@code .fdg}
 * side-file reader (odd), the rest is the file. Any bytes are a network (or layout) or a
 * {@link NetworkFileException} whose every problem names the file — never another exception, an external entity
 * fetched, or a hang. What is read is written in canonical form, and that form reads back and writes the same
 * bytes (what {@code fdnet fmt} relies on). Seeds (the example networks) and kept findings:
 * {@code src/test/resources/org/fdnet/netinfo/xml/NetworkFileFuzzTestInputs/}.
 */
class NetworkFileFuzzTest {
    private static final Path NETWORK = Path.of("fuzz.fdn");
    private static final Path LAYOUT = Path.of("fuzz.fdg");

    @FuzzTest(maxDuration = "10m")
    void shouldReadOrReportEveryProblem(byte[] input) throws Exception {
        if (input.length == 0) {
            return;
        }
        byte[] file = Arrays.copyOfRange(input, 1, input.length);
        Path source = (input[0] & 1) == 0 ? NETWORK : LAYOUT;
        try {
            if (source == NETWORK) {
                readNetwork(file);
            } else {
                readLayout(file);
            }
        } catch (NetworkFileException refused) {
            assertThat(refused.problems()).isNotEmpty()
                    .allSatisfy(p -> assertThat(p.toString()).startsWith(source + ":"));
        }
    }

    private static void readNetwork(byte[] file) throws NetworkFileException {
        NetworkInfo network = new NetworkFileReader(NETWORK, file).read().network();
        byte[] canonical = NetworkRepository.toBytes(network, NetworkRepository.DEFAULT_SYSTEM_ID);
        NetworkInfo again = new NetworkFileReader(Path.of("canonical.fdn"), canonical).read().network();
        assertThat(NetworkRepository.toBytes(again, NetworkRepository.DEFAULT_SYSTEM_ID)).isEqualTo(canonical);
    }

    private static void readLayout(byte[] file) throws NetworkFileException, IOException {
        byte[] canonical = bytes(LayoutRepository.read(LAYOUT, file));
        assertThat(bytes(LayoutRepository.read(Path.of("canonical.fdg"), canonical))).isEqualTo(canonical);
    }

    private static byte[] bytes(NetworkLayout layout) throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        LayoutRepository.write(layout, out);
        return out.toByteArray();
    }
}
