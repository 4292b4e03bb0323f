package org.fdnet.cli;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Properties;

/**
 * The FDNet checkout {@code bin/fdnet} runs from (its {@code fdnet.home}) and the versions the build stamped into
 * this class path: what {@code fdnet sdk install} installs and what {@code fdnet new nodes} generates with.
 *
 * @param root                   the checkout's folder (where its parent pom.xml is)
 * @param version                the version of every FDNet artifact, the BOM's included
 * @param archetypePluginVersion the maven-archetype-plugin version the build itself uses
 */
record FdnetSdk(Path root, String version, String archetypePluginVersion) {
    static final String GROUP_ID = "org.fdnet";
    static final String BOM = "fdnet-bom";
    static final String ARCHETYPE = "fdnet-nodes-archetype";

    /**
     * The checkout of this JVM, from the system property {@code fdnet.home} that bin/fdnet sets.
     *
     * @throws IllegalStateException with the sentence to print when there is none
     */
    static FdnetSdk current() {
        String home = System.getProperty("fdnet.home");
        if (home == null || home.isBlank()) {
            throw new IllegalStateException("fdnet.home is not set: run this command through bin/fdnet in an FDNet checkout");
        }
        Path root = Path.of(home).toAbsolutePath().normalize();
        if (!Files.isRegularFile(root.resolve("pom.xml"))) {
            throw new IllegalStateException("fdnet.home " + root + " has no pom.xml: it must be the FDNet checkout bin/fdnet is in");
        }
        Properties stamped = new Properties();
        try (InputStream in = FdnetSdk.class.getResourceAsStream("sdk.properties")) {
            if (in == null) {
                throw new IllegalStateException("org/fdnet/cli/sdk.properties is missing from the class path: rebuild FDNet");
            }
            stamped.load(in);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read org/fdnet/cli/sdk.properties", e);
        }
        return new FdnetSdk(root, stamped.getProperty("fdnet.version"), stamped.getProperty("archetype.plugin.version"));
    }

    /** The lines a project's pom.xml needs to name every FDNet artifact without a version. */
    String bomImport() {
        return String.join(System.lineSeparator(),
                "<dependencyManagement>",
                "  <dependencies>",
                "    <dependency>",
                "      <groupId>" + GROUP_ID + "</groupId>",
                "      <artifactId>" + BOM + "</artifactId>",
                "      <version>" + version + "</version>",
                "      <type>pom</type>",
                "      <scope>import</scope>",
                "    </dependency>",
                "  </dependencies>",
                "</dependencyManagement>");
    }
}
