package org.fdnet.testing;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.jar.JarEntry;
import java.util.jar.JarOutputStream;
import java.util.stream.Stream;
import javax.tools.ToolProvider;

/** Node classes made in a test, as a user's build makes them: compiled against the test's class path, then jarred. */
public final class NodeJars {
    private NodeJars() {
    }

    /**
     * Compiles class {@code plugin.NAME} with {@code body} (the class declaration) into {@code folder}.
     *
     * @return {@code folder}
     */
    public static Path compile(Path folder, String name, String body) throws IOException {
        Path src = Files.createDirectories(folder.resolve("src/plugin")).resolve(name + ".java");
        Files.writeString(src, "package plugin;\n" + body);
        int rc = ToolProvider.getSystemJavaCompiler().run(null, null, null, "-d", folder.toString(), "-cp",
                System.getProperty("java.class.path"), src.toString());
        assertThat(rc).as("javac of " + name).isZero();
        return folder;
    }

    /** Compiles {@code plugin.Emit}, a Relation that writes {@code constant} to its outputs, into {@code folder}. */
    public static Path compileEmit(Path folder, String constant) throws IOException {
        return compile(folder, "Emit", "public class Emit extends org.fdnet.runtime.Relation {\n"
                + "  protected void compute(org.fdnet.runtime.RelationContext c) {\n"
                + "    c.outputAll(org.fdnet.runtime.Value.of(" + constant + ".0));\n  }\n}\n");
    }

    /** Writes every class file under {@code classes} into a new jar {@code jar} (its folder is made). */
    public static Path jar(Path classes, Path jar) throws IOException {
        Files.createDirectories(jar.getParent());
        try (JarOutputStream out = new JarOutputStream(Files.newOutputStream(jar));
             Stream<Path> files = Files.walk(classes)) {
            for (Path f : files.filter(p -> p.toString().endsWith(".class")).toList()) {
                out.putNextEntry(new JarEntry(classes.relativize(f).toString().replace('\\', '/')));
                out.write(Files.readAllBytes(f));
                out.closeEntry();
            }
        }
        return jar;
    }
}
