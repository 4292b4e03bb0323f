package org.fdnet.architecture;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import javax.xml.parsers.DocumentBuilderFactory;
import org.junit.jupiter.api.Test;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.Node;
import org.w3c.dom.NodeList;

/**
 * The BOM (fdnet-core/bom) has no parent, so nothing keeps it in step with the reactor but this test: it must carry
 * the reactor's version and manage exactly the artifacts a user's project builds on — every module that ships
 * sources and javadoc jars (the bench modules, the launcher, the BOM and the archetype do not) — and build with the
 * parent's plugin versions.
 */
class BomTest {
    private static final Path ROOT = Path.of("../..").toAbsolutePath().normalize();

    @Test
    void shouldCarryTheReactorsVersion() throws Exception {
        Element bom = pom(ROOT.resolve("fdnet-core/bom/pom.xml"));
        Element parent = pom(ROOT.resolve("pom.xml"));
        assertThat(child(bom, "version")).isEqualTo(child(parent, "version"));
        assertThat(property(bom, "fdnet.version")).isEqualTo(child(parent, "version"));
    }

    @Test
    void shouldManageEveryArtifactAUserBuildsOnAndNothingElse() throws Exception {
        Element bom = pom(ROOT.resolve("fdnet-core/bom/pom.xml"));
        Set<String> managed = new TreeSet<>();
        NodeList dependencies = bom.getElementsByTagName("dependency");
        for (int i = 0; i < dependencies.getLength(); i++) {
            Element dependency = (Element) dependencies.item(i);
            assertThat(child(dependency, "version")).as(child(dependency, "artifactId")).isEqualTo("${fdnet.version}");
            managed.add(child(dependency, "groupId") + ":" + child(dependency, "artifactId"));
        }
        assertThat(managed).isEqualTo(userArtifacts());
    }

    @Test
    void shouldBuildWithThePluginVersionsOfTheParent() throws Exception {
        Element bom = pom(ROOT.resolve("fdnet-core/bom/pom.xml"));
        Element parent = pom(ROOT.resolve("pom.xml"));
        Map<String, String> parentVersions = new TreeMap<>();
        NodeList parentPlugins = parent.getElementsByTagName("plugin");
        for (int i = 0; i < parentPlugins.getLength(); i++) {
            Element plugin = (Element) parentPlugins.item(i);
            String version = child(plugin, "version");
            if (version != null) {
                parentVersions.put(child(plugin, "artifactId"), version.startsWith("${")
                        ? property(parent, version.substring(2, version.length() - 1)) : version);
            }
        }
        NodeList plugins = bom.getElementsByTagName("plugin");
        assertThat(plugins.getLength()).as("plugins pinned in the BOM").isGreaterThan(0);
        for (int i = 0; i < plugins.getLength(); i++) {
            Element plugin = (Element) plugins.item(i);
            String artifactId = child(plugin, "artifactId");
            assertThat(child(plugin, "version")).as(artifactId).isEqualTo(parentVersions.get(artifactId));
        }
    }

    /** groupId:artifactId of every reactor module that is a jar shipped with sources and javadoc. */
    private static Set<String> userArtifacts() throws Exception {
        Set<String> artifacts = new TreeSet<>();
        for (String module : modules()) {
            Element pom = pom(ROOT.resolve(module).resolve("pom.xml"));
            String packaging = child(pom, "packaging");
            boolean jar = packaging == null || packaging.equals("jar");
            if (jar && !"true".equals(property(pom, "fdnet.sdk.jars.skip"))) {
                artifacts.add("org.fdnet:" + child(pom, "artifactId"));
            }
        }
        return artifacts;
    }

    private static List<String> modules() throws Exception {
        List<String> modules = new ArrayList<>();
        NodeList list = pom(ROOT.resolve("pom.xml")).getElementsByTagName("module");
        for (int i = 0; i < list.getLength(); i++) {
            modules.add(list.item(i).getTextContent().trim());
        }
        assertThat(modules).as("the reactor's modules").contains("fdnet-core/bom", "fdnet-core/api");
        return modules;
    }

    private static Element pom(Path file) throws Exception {
        assertThat(file).exists();
        DocumentBuilderFactory factory = DocumentBuilderFactory.newInstance();
        factory.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
        try (var in = Files.newInputStream(file)) {
            Document document = factory.newDocumentBuilder().parse(in);
            return document.getDocumentElement();
        }
    }

    /** The text of {@code element}'s direct child named {@code name}, or null. */
    private static String child(Element element, String name) {
        for (Node n = element.getFirstChild(); n != null; n = n.getNextSibling()) {
            if (n instanceof Element e && e.getTagName().equals(name)) {
                return e.getTextContent().trim();
            }
        }
        return null;
    }

    private static String property(Element project, String name) {
        for (Node n = project.getFirstChild(); n != null; n = n.getNextSibling()) {
            if (n instanceof Element e && e.getTagName().equals("properties")) {
                return child(e, name);
            }
        }
        return null;
    }
}
