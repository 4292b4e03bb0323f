package org.fdnet.runtime.loading;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Enumeration;
import java.util.List;
import java.util.Locale;
import java.util.jar.JarEntry;
import java.util.jar.JarFile;
import java.util.stream.Stream;

/**
 * The class names a node path holds, read from file names only (nothing is loaded): a jar's entries; or a folder's
 * {@code .class} files (packages as sub-folders) and the entries of every jar directly in the folder — what the
 * path's class loader sees. {@code module-info}, {@code package-info} and {@code META-INF} are left out.
 */
final class NodeClassScanner {
    private static final String CLASS_SUFFIX = ".class";

    private NodeClassScanner() {
    }

    static boolean isJar(Path file) {
        return Files.isRegularFile(file) && file.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".jar");
    }

    /** The jars directly in {@code folder}, by name. */
    static List<Path> jarsIn(Path folder) throws IOException {
        try (Stream<Path> files = Files.list(folder)) {
            return files.filter(NodeClassScanner::isJar).sorted().toList();
        }
    }

    /** Every class name on the path (a jar, or a folder with its jars), in the order found. */
    static List<String> classNames(Path path) throws IOException {
        List<String> names = new ArrayList<>();
        if (isJar(path)) {
            addJar(path, names);
            return names;
        }
        try (Stream<Path> files = Files.walk(path)) {
            files.filter(f -> Files.isRegularFile(f) && f.getFileName().toString().endsWith(CLASS_SUFFIX))
                    .map(f -> path.relativize(f).toString().replace(f.getFileSystem().getSeparator(), "/"))
                    .forEach(entry -> add(entry, names));
        }
        for (Path jar : jarsIn(path)) {
            addJar(jar, names);
        }
        return names;
    }

    private static void addJar(Path jar, List<String> names) throws IOException {
        try (JarFile file = new JarFile(jar.toFile())) {
            Enumeration<JarEntry> entries = file.entries();
            while (entries.hasMoreElements()) {
                JarEntry e = entries.nextElement();
                if (!e.isDirectory()) {
                    add(e.getName(), names);
                }
            }
        }
    }

    private static void add(String entry, List<String> names) {
        if (!entry.endsWith(CLASS_SUFFIX) || entry.startsWith("META-INF/")) {
            return;
        }
        String name = entry.substring(0, entry.length() - CLASS_SUFFIX.length()).replace('/', '.');
        if (!name.equals("module-info") && !name.endsWith(".package-info") && !name.equals("package-info")) {
            names.add(name);
        }
    }
}
