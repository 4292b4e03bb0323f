package org.fdnet.netinfo.xml;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeRef;
import org.junit.jupiter.api.Test;

class NestedModuleFilesTest {
    private static final Path EXAMPLE = Path.of("../networks/nested-arm.fdn");

    @Test
    void shouldReadNestedModulesAsPathsWithTheirReferencesResolved() throws Exception {
        NetworkInfo n = NetworkRepository.load(EXAMPLE);
        assertThat(n.modules()).extracting(ModuleInfo::name)
                .containsExactly("main", "Arm", "Arm/Hand", "Arm/Hand/Fingers", "Arm/Wrist");
        assertThat(n.module("Arm/Hand").loadAtStart()).isTrue();
        assertThat(n.module("Arm/Hand/Fingers").loadAtStart()).isFalse();
        // Fingers' bare "Grip" is its parent's; Wrist names it by path
        assertThat(n.connectionsOf(new NodeRef("Arm/Hand", "Grip")))
                .extracting(lc -> lc.module()).contains("Arm/Hand/Fingers", "Arm/Wrist");
    }

    @Test
    void shouldWriteNestedModulesBackInsideTheirParentsUnchanged() throws Exception {
        String original = Files.readString(EXAMPLE, StandardCharsets.UTF_8);
        NetworkInfo n = NetworkRepository.load(EXAMPLE);
        String written = new String(NetworkRepository.toBytes(n, "../dtd/cnet.dtd", NetworkRepository.read(EXAMPLE).leadingComments()),
                StandardCharsets.UTF_8);
        assertThat(written).isEqualTo(original);
        assertThat(NetworkRepository.fromText(written, "again")).isEqualTo(n);
    }

    @Test
    void shouldKeepA2004FileWithFlatModulesValidAndUnchanged() throws Exception {
        Path arms = Path.of("../networks/arms.fdn");
        NetworkInfo n = NetworkRepository.load(arms);
        assertThat(n.modules()).extracting(ModuleInfo::parentName).containsOnlyNulls();
        String written = new String(NetworkRepository.toBytes(n, "../dtd/cnet.dtd", NetworkRepository.read(arms).leadingComments()),
                StandardCharsets.UTF_8);
        assertThat(written).isEqualTo(Files.readString(arms, StandardCharsets.UTF_8));
    }

    @Test
    void shouldRejectASlashInANestedModulesNameAtItsLine() {
        String text = "<?xml version=\"1.0\"?>\n<cnet>\n<module name=\"A\">\n<module name=\"B/C\"/>\n</module>\n</cnet>\n";
        assertThatThrownBy(() -> NetworkRepository.fromText(text, "bad.fdn"))
                .isInstanceOf(NetworkFileException.class)
                .hasMessageContaining("bad.fdn:4:").hasMessageContaining("may not contain '/'");
    }

    @Test
    void shouldRejectAReferenceNoEnclosingModuleResolves() {
        String text = "<?xml version=\"1.0\"?>\n<cnet>\n<module name=\"A\">\n<module name=\"B\">\n"
                + "<pstructure><name>R</name><host>h</host><path></path><class>C</class></pstructure>\n"
                + "<connection><write><data>Nowhere</data><proc>R</proc></write></connection>\n</module>\n</module>\n</cnet>\n";
        assertThatThrownBy(() -> NetworkRepository.fromText(text, "bad.fdn"))
                .hasMessageContaining("neither module 'A/B', the modules enclosing it, nor module 'main'");
    }
}
