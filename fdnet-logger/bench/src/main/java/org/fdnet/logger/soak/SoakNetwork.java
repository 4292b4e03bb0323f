package org.fdnet.logger.soak;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * The soak's network: {@code two-robots} as it is, plus a counted path across both links — {@code Seq} (a whole number
 * the soak writes) on the flyer, {@code Relay} on the crawler copying it into {@code Echo}, which the operator reads.
 */
final class SoakNetwork {
    private static final String NODES = """
                <dstructure>
                    <name>Seq</name>
                    <host>flyer</host>
                    <path></path>
                    <class>org.fdnet.runtime.library.LongData</class>
                </dstructure>
                <pstructure>
                    <name>Relay</name>
                    <host>crawler</host>
                    <path></path>
                    <class>org.fdnet.runtime.library.Expression</class>
                    <param name="expression">Seq</param>
                </pstructure>
                <dstructure>
                    <name>Echo</name>
                    <host>crawler</host>
                    <path></path>
                    <class>org.fdnet.runtime.library.DoubleData</class>
                </dstructure>
            """;
    private static final String CONNECTIONS = """
                    <read>
                        <data>Seq</data>
                        <proc>Relay</proc>
                    </read>
                    <write>
                        <data>Echo</data>
                        <proc>Relay</proc>
                    </write>
                    <read>
                        <data>Echo</data>
                        <proc>Operator</proc>
                    </read>
            """;

    private SoakNetwork() {
    }

    /**
     * Writes the soak's network next to nothing else: {@code work/soak.fdn} (the DTD reference made absolute).
     *
     * @throws IOException when {@code twoRobots} cannot be read or is not the expected example
     */
    static Path write(Path twoRobots, Path work) throws IOException {
        String text = Files.readString(twoRobots, StandardCharsets.UTF_8);
        int connection = text.indexOf("<connection>");
        if (connection < 0 || !text.contains("../dtd/cnet.dtd") || !text.contains("<name>Operator</name>")) {
            throw new IOException(twoRobots + " is not the two-robots example the soak extends (no Operator,"
                    + " <connection> or ../dtd/cnet.dtd)");
        }
        int afterConnection = connection + "<connection>".length();
        String soak = text.substring(0, connection).stripTrailing() + "\n" + NODES + "    <connection>\n" + CONNECTIONS
                + text.substring(afterConnection).stripLeading();
        soak = soak.replace("../dtd/cnet.dtd", twoRobots.toAbsolutePath().getParent().resolve("../dtd/cnet.dtd")
                .normalize().toString());
        Path file = work.resolve("soak.fdn");
        Files.writeString(file, soak, StandardCharsets.UTF_8);
        return file;
    }
}
