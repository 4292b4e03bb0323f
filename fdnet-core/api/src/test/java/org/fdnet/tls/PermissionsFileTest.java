package org.fdnet.tls;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The permissions file is read only when the network's CA signed exactly its bytes. */
class PermissionsFileTest {
    private static final String VIEWER_READS = "* read *\nviewer record\n";

    @Test
    void shouldLoadTheDefaultThatKeysWritesAndAllowEverything() {
        TlsIdentity tls = TlsIdentity.load(TestKeys.network("tester"));
        assertThat(tls.permissions().refusal("someone", Right.WRITE, "main", "Certainty")).isNull();
        assertThat(tls.permissions().refusal("someone", Right.UNLOAD, "Gait")).isNull();
    }

    @Test
    void shouldLoadAFileSignedAgainAfterEditing() {
        Path dir = TestKeys.withPermissions("permissions-signed", VIEWER_READS, List.of("viewer"));
        Permissions p = TlsIdentity.load(dir.resolve("viewer.p12")).permissions();
        assertThat(p.refusal("viewer", Right.READ, "main", "Certainty")).isNull();
        assertThat(p.refusal("viewer", Right.WRITE, "main", "Certainty")).contains("'viewer' may not write");
    }

    @Test
    void shouldRefuseATamperedFileNamingItAndWhatIsWrong() throws Exception {
        Path dir = TestKeys.withPermissions("permissions-tampered", VIEWER_READS, List.of("viewer"));
        Path file = dir.resolve(PermissionsFile.FILE);
        Files.writeString(file, VIEWER_READS + "viewer write *\n", StandardCharsets.UTF_8);
        assertThatThrownBy(() -> TlsIdentity.load(dir.resolve("viewer.p12")))
                .isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining(file.toString()).hasMessageContaining("does not match its signature")
                .hasMessageContaining("--sign-permissions");
    }

    @Test
    void shouldRefuseAFileSignedByAnotherNetworksCa() throws Exception {
        Path dir = TestKeys.withPermissions("permissions-foreign-signature", VIEWER_READS, List.of("viewer"));
        Path foreign = TestKeys.withPermissions("permissions-foreign-ca", VIEWER_READS + "viewer write *\n",
                List.of("intruder"));
        Files.copy(foreign.resolve(PermissionsFile.FILE), dir.resolve(PermissionsFile.FILE),
                java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        Files.copy(foreign.resolve(PermissionsFile.SIGNATURE), dir.resolve(PermissionsFile.SIGNATURE),
                java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        assertThatThrownBy(() -> TlsIdentity.load(dir.resolve("viewer.p12")))
                .hasMessageContaining("does not match its signature").hasMessageContaining("another CA");
    }

    @Test
    void shouldRefuseAnUnsignedOrMissingFile() throws Exception {
        Path dir = TestKeys.withPermissions("permissions-unsigned", VIEWER_READS, List.of("viewer"));
        Files.delete(dir.resolve(PermissionsFile.SIGNATURE));
        assertThatThrownBy(() -> TlsIdentity.load(dir.resolve("viewer.p12")))
                .hasMessageContaining(dir.resolve(PermissionsFile.FILE).toString()).hasMessageContaining("is not signed");
        Files.delete(dir.resolve(PermissionsFile.FILE));
        assertThatThrownBy(() -> TlsIdentity.load(dir.resolve("viewer.p12")))
                .hasMessageContaining("is missing").hasMessageContaining("fdnet keys --out");
    }

    @Test
    void shouldRefuseToSignAnInvalidFile() throws Exception {
        Path dir = TestKeys.withPermissions("permissions-invalid", VIEWER_READS, List.of("viewer"));
        String signed = Files.readString(dir.resolve(PermissionsFile.SIGNATURE));
        Files.writeString(dir.resolve(PermissionsFile.FILE), "viewer wirte *\n");
        assertThatThrownBy(() -> new KeyMaker(dir).signPermissions()).hasMessageContaining(":1: unknown right 'wirte'");
        assertThat(Files.readString(dir.resolve(PermissionsFile.SIGNATURE))).as("the old signature kept").isEqualTo(signed);
    }
}
