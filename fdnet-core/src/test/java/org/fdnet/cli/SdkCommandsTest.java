package org.fdnet.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.fdnet.testing.CliRun;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class SdkCommandsTest {
    @TempDir
    Path dir;

    private final CliRun cli = new CliRun();

    @Test
    void installProgressShouldTellOneLinePerModuleWithTheKindsOfFileInstalled() {
        List<InstallProgress.Installed> told = new ArrayList<>();
        InstallProgress progress = new InstallProgress(told::add);
        List.of(
                "[INFO] Building FDNet BOM 0.1.0-SNAPSHOT                                  [1/2]",
                "[INFO] --- maven-install-plugin:3.1.3:install (default-install) @ fdnet-bom ---",
                "[INFO] Installing /src/fdnet-core/bom/pom.xml to /m2/org/fdnet/fdnet-bom/0.1.0-SNAPSHOT/fdnet-bom-0.1.0-SNAPSHOT.pom",
                "[INFO] ",
                "[INFO] Building FDNet API 0.1.0-SNAPSHOT                                  [2/2]",
                "[INFO] --- maven-jar-plugin:3.4.2:jar (default-jar) @ fdnet-api ---",
                "[INFO] Building jar: /src/fdnet-core/api/target/fdnet-api-0.1.0-SNAPSHOT.jar",
                "[INFO] --- maven-install-plugin:3.1.3:install (default-install) @ fdnet-api ---",
                "[INFO] Installing /src/fdnet-core/api/pom.xml to /m2/org/fdnet/fdnet-api/0.1.0-SNAPSHOT/fdnet-api-0.1.0-SNAPSHOT.pom",
                "[INFO] Installing /src/a.jar to /m2/org/fdnet/fdnet-api/0.1.0-SNAPSHOT/fdnet-api-0.1.0-SNAPSHOT.jar",
                "[INFO] Installing /src/b.jar to /m2/org/fdnet/fdnet-api/0.1.0-SNAPSHOT/fdnet-api-0.1.0-SNAPSHOT-sources.jar",
                "[INFO] Installing /src/c.jar to /m2/org/fdnet/fdnet-api/0.1.0-SNAPSHOT/fdnet-api-0.1.0-SNAPSHOT-javadoc.jar",
                "[INFO] ------------------------------------------------------------------------",
                "[INFO] Reactor Summary for FDNet 0.1.0-SNAPSHOT:").forEach(progress);

        assertThat(told).extracting(InstallProgress.Installed::artifactId).containsExactly("fdnet-bom", "fdnet-api");
        assertThat(told.get(0).position()).isEqualTo("[1/2]");
        assertThat(told.get(1).position()).isEqualTo("[2/2]");
        assertThat(told.get(1).kinds()).containsExactly("pom", "jar", "sources", "javadoc");
        assertThat(progress.commonFolder()).isEqualTo(Path.of("/m2/org/fdnet"));
    }

    @Test
    void installProgressShouldTellNothingForAModuleThatInstalledNothing() {
        List<InstallProgress.Installed> told = new ArrayList<>();
        InstallProgress progress = new InstallProgress(told::add);
        progress.accept("[INFO] --- maven-install-plugin:3.1.3:install (default-install) @ fdnet-api ---");
        progress.accept("[INFO] BUILD FAILURE");
        progress.finishModule();
        assertThat(told).isEmpty();
        assertThat(progress.commonFolder()).isNull();
    }

    @Test
    void newNodesShouldRefuseAFolderThatIsNotEmptyInOneLine() throws Exception {
        Path lab = Files.createDirectories(dir.resolve("lab"));
        Files.writeString(lab.resolve("notes.txt"), "mine");
        assertThat(cli.fdnet("new", "nodes", lab.toString())).isEqualTo(1);
        assertThat(cli.output().strip()).isEqualTo("fdnet new nodes: " + lab + " already exists and is not an empty folder; name a new one");
        assertThat(Files.readString(lab.resolve("notes.txt"))).isEqualTo("mine");
    }

    @Test
    void newNodesShouldRefuseAPackageThatIsNotAJavaPackage() {
        assertThat(cli.fdnet("new", "nodes", dir.resolve("lab").toString(), "--package", "Org.Example-Lab")).isEqualTo(1);
        assertThat(cli.output()).contains("--package 'Org.Example-Lab' is not a Java package name");
        assertThat(dir.resolve("lab")).doesNotExist();
    }

    @Test
    void newNodesShouldDeriveAJavaPackageFromGroupAndFolderName() {
        assertThat(NewNodesCommand.defaultPackage("org.example", "my-lab")).isEqualTo("org.example.mylab");
        assertThat(NewNodesCommand.defaultPackage("com.acme", "2nd.Lab")).isEqualTo("com.acme._2nd.lab");
    }

    @Test
    void newNodesShouldGenerateWithFdnetsArchetypeOfThisVersionOfflineAndNonInteractive() {
        FdnetSdk sdk = new FdnetSdk(dir, "1.2.3", "3.3.1");
        assertThat(NewNodesCommand.generate(sdk, dir, "lab", "org.example.lab", "org.example"))
                .contains("-B", "-o", "org.apache.maven.plugins:maven-archetype-plugin:3.3.1:generate",
                        "-DinteractiveMode=false", "-DarchetypeGroupId=org.fdnet",
                        "-DarchetypeArtifactId=fdnet-nodes-archetype", "-DarchetypeVersion=1.2.3",
                        "-DartifactId=lab", "-Dpackage=org.example.lab", "-DoutputDirectory=" + dir);
    }

    @Test
    void sdkShouldStampTheProjectsVersionIntoTheClassPath() {
        String home = System.getProperty("fdnet.home");
        System.setProperty("fdnet.home", Path.of("..").toAbsolutePath().normalize().toString());
        try {
            FdnetSdk sdk = FdnetSdk.current();
            assertThat(sdk.version()).matches("\\d+\\.\\d+\\.\\d+(-SNAPSHOT)?");
            assertThat(sdk.archetypePluginVersion()).matches("\\d+\\.\\d+\\.\\d+");
            assertThat(sdk.bomImport()).contains("<artifactId>fdnet-bom</artifactId>", "<version>" + sdk.version() + "</version>",
                    "<scope>import</scope>");
        } finally {
            restore(home);
        }
    }

    @Test
    void sdkInstallShouldSayHowToRunItWithoutTheLauncher() {
        String home = System.getProperty("fdnet.home");
        System.clearProperty("fdnet.home");
        try {
            assertThat(cli.fdnet("sdk", "install")).isEqualTo(1);
            assertThat(cli.output().strip())
                    .isEqualTo("fdnet sdk install: fdnet.home is not set: run this command through bin/fdnet in an FDNet checkout");
        } finally {
            restore(home);
        }
    }

    private static void restore(String home) {
        if (home == null) {
            System.clearProperty("fdnet.home");
        } else {
            System.setProperty("fdnet.home", home);
        }
    }
}
