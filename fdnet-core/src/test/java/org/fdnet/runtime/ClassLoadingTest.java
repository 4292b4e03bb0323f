package org.fdnet.runtime;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.fdnet.runtime.TestNetworks.*;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.fdnet.runtime.engine.RuntimeOptions;
import org.fdnet.runtime.loading.ClassLoadingPolicy;
import org.fdnet.runtime.loading.NodeClassException;
import org.fdnet.runtime.loading.NodeClassResolver;
import org.fdnet.testing.NodeJars;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

@Timeout(60)
class ClassLoadingTest {
    @TempDir
    Path dir;

    private RuntimeOptions optionsFor(Path networkFile) {
        return RuntimeOptions.defaults().workerThreads(1)
                .classLoading(ClassLoadingPolicy.forNetworkFile(networkFile, List.of()));
    }

    private static NodeInfo relationAt(String name, String path, String cls) {
        return new NodeInfo(NodeKind.RELATION, name, "localhost", path, cls, List.of());
    }

    @Test
    void shouldRefuseAnUnknownBuiltInClassNamingModuleNodeAndClass() {
        NetworkInfo n = new NetworkInfo("x");
        n.addModule("Arm", true);
        n.addNode("Arm", relation("Servo", "org.fdnet.runtime.library.NoSuchThing"));
        assertThatThrownBy(() -> RuntimeNetwork.start(n, optionsFor(dir.resolve("x.fdn"))))
                .hasMessageContaining("module 'Arm', node 'Servo', class 'org.fdnet.runtime.library.NoSuchThing'")
                .hasMessageContaining("no such built-in class");
    }

    @Test
    void shouldRefuseADataClassUsedAsARelation() {
        NetworkInfo n = new NetworkInfo("x");
        n.addNode("main", relation("Oops", "DoubleData"));
        assertThatThrownBy(() -> RuntimeNetwork.start(n, optionsFor(dir.resolve("x.fdn"))))
                .hasMessageContaining("node 'Oops'")
                .hasMessageContaining("the node is a Relation but its class is a Data class");
    }

    @Test
    void shouldRefuseAnyClassOutsideTheBuiltInPackagesWithoutAPath() {
        NetworkInfo n = new NetworkInfo("x");
        n.addNode("main", relation("Evil", "java.lang.Thread"));
        assertThatThrownBy(() -> RuntimeNetwork.start(n, optionsFor(dir.resolve("x.fdn"))))
                .hasMessageContaining("class 'java.lang.Thread'").hasMessageContaining("must be built in");
    }

    @Test
    void shouldRefuseAPathOutsideTheAllowedRoots() throws Exception {
        Path network = Files.createDirectories(dir.resolve("net")).resolve("x.fdn");
        Files.createDirectories(dir.resolve("elsewhere"));
        NetworkInfo n = new NetworkInfo("x");
        n.addNode("main", relationAt("Plugin", "../elsewhere", "p.Thing"));
        assertThatThrownBy(() -> RuntimeNetwork.start(n, optionsFor(network)))
                .hasMessageContaining("node 'Plugin'").hasMessageContaining("outside the allowed places");
    }

    @Test
    void shouldLoadEachPathsClassesWithTheirOwnLoader() throws Exception {
        NodeJars.compileEmit(dir.resolve("one"), "10");
        NodeJars.compileEmit(dir.resolve("two"), "20");
        // same class name, two folders: two classes, each with its own constant
        assertThat(written("one", "plugin.Emit", "two", "plugin.Emit")).containsExactly(10.0, 20.0);
    }

    @Test
    void shouldRefuseAClassMissingFromItsPath() throws Exception {
        NodeJars.compileEmit(dir.resolve("one"), "1");
        NetworkInfo n = new NetworkInfo("x");
        n.addNode("main", relationAt("Lost", "one", "plugin.Missing"));
        assertThatThrownBy(() -> RuntimeNetwork.start(n, optionsFor(dir.resolve("x.fdn"))))
                .hasMessageContaining("class 'plugin.Missing'").hasMessageContaining("class not found under");
    }

    @Test
    void shouldRunANodeFromAJarBuiltInTheTest() throws Exception {
        NodeJars.jar(NodeJars.compileEmit(dir.resolve("classes"), "10"), dir.resolve("lib").resolve("emit.jar"));
        NodeJars.jar(NodeJars.compileEmit(dir.resolve("other"), "20"), dir.resolve("lib").resolve("other.jar"));
        assertThat(written("lib/emit.jar", "plugin.Emit", "lib/other.jar", "plugin.Emit")).containsExactly(10.0, 20.0);
    }

    @Test
    void shouldRunNodesFromAFolderOfJarsAndItsClasses() throws Exception {
        Path jars = Files.createDirectories(dir.resolve("jars"));
        NodeJars.jar(NodeJars.compileEmit(dir.resolve("classes"), "30"), jars.resolve("emit.jar"));
        NodeJars.compile(jars, "Loose", "public class Loose extends org.fdnet.runtime.Relation {\n"
                + "  protected void compute(org.fdnet.runtime.RelationContext c) {\n"
                + "    c.outputAll(org.fdnet.runtime.Value.of(7.0));\n  }\n}\n");
        assertThat(written("jars", "plugin.Emit", "jars", "plugin.Loose")).containsExactly(30.0, 7.0);
    }

    /**
     * Runs a network of {@code x.fdn} in the test folder where Relation First (class {@code firstClass} on
     * {@code firstPath}) writes Data A and Second writes B, and returns what A and B hold once it is quiet.
     */
    private double[] written(String firstPath, String firstClass, String secondPath, String secondClass)
            throws Exception {
        NetworkInfo n = new NetworkInfo("x");
        n.addNode("main", data("A", "DoubleData"));
        n.addNode("main", data("B", "DoubleData"));
        n.addNode("main", relationAt("First", firstPath, firstClass));
        n.addNode("main", relationAt("Second", secondPath, secondClass));
        write(n, "main", "First", "A");
        write(n, "main", "Second", "B");
        try (RuntimeNetwork net = RuntimeNetwork.start(n, optionsFor(dir.resolve("x.fdn")))) {
            quiet(net);
            return new double[] {net.controller().value(ref("A")).asDouble(), net.controller().value(ref("B")).asDouble()};
        }
    }

    @Test
    void shouldRefuseAJarOutsideTheAllowedPlaces() throws Exception {
        Path network = Files.createDirectories(dir.resolve("net")).resolve("x.fdn");
        NodeJars.jar(NodeJars.compileEmit(dir.resolve("classes"), "1"), dir.resolve("elsewhere").resolve("emit.jar"));
        NetworkInfo n = new NetworkInfo("x");
        n.addNode("main", relationAt("Plugin", "../elsewhere/emit.jar", "plugin.Emit"));
        assertThatThrownBy(() -> RuntimeNetwork.start(n, optionsFor(network)))
                .hasMessageContaining("module 'main', node 'Plugin', class 'plugin.Emit'")
                .hasMessageContaining("path '../elsewhere/emit.jar'").hasMessageContaining("outside the allowed places");
    }

    @Test
    void shouldOfferTheConcreteNodeClassesOfAPathWithoutInitialisingThem() throws Exception {
        Path classes = NodeJars.compileEmit(dir.resolve("classes"), "1");
        NodeJars.compile(classes, "Noisy", "public class Noisy extends org.fdnet.runtime.library.DoubleData {\n"
                + "  static { System.setProperty(\"fdnet.test.noisy\", \"initialised\"); }\n}\n");
        NodeJars.compile(classes, "Half", "public abstract class Half extends org.fdnet.runtime.Relation {}\n");
        NodeJars.compile(classes, "Picky", "public class Picky extends org.fdnet.runtime.Relation {\n"
                + "  public Picky(int x) {}\n"
                + "  protected void compute(org.fdnet.runtime.RelationContext c) {}\n}\n");
        NodeJars.compile(classes, "Plain", "public class Plain {}\n");
        NodeJars.jar(classes, dir.resolve("lib").resolve("nodes.jar"));
        try (NodeClassResolver resolver = new NodeClassResolver(ClassLoadingPolicy.forNetworkFile(dir.resolve("x.fdn"),
                List.of()), Data.class, Relation.class)) {
            assertThat(resolver.nodeClassesOn("lib/nodes.jar")).extracting(Class::getName)
                    .containsExactly("plugin.Emit", "plugin.Noisy");
            assertThat(resolver.nodeClassesOn("lib")).extracting(Class::getName)
                    .containsExactly("plugin.Emit", "plugin.Noisy");
            assertThatThrownBy(() -> resolver.nodeClassesOn("../"))
                    .isInstanceOf(NodeClassException.class).hasMessageContaining("outside the allowed places");
        }
        assertThat(System.getProperty("fdnet.test.noisy")).isNull();
    }
}
