package org.fdnet.cli;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.function.Consumer;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Reads the output of {@code mvn -B install} line by line and tells one line per module installed:
 * {@code [3/14] fdnet-core: jar, sources, javadoc}. What Maven prints (for every module, in reactor order):
 *
 * <pre>
 *   [INFO] Building FDNet core 0.1.0-SNAPSHOT                                [3/14]
 *   ...
 *   [INFO] --- maven-install-plugin:3.1.3:install (default-install) @ fdnet-core ---
 *   [INFO] Installing /…/fdnet-core/target/fdnet-core-0.1.0-SNAPSHOT.jar to /…/.m2/repository/org/fdnet/fdnet-core/…/fdnet-core-0.1.0-SNAPSHOT.jar
 * </pre>
 *
 * A module's installed files end at the next plugin, module or the reactor summary.
 */
final class InstallProgress implements Consumer<String> {
    private static final Pattern BUILDING = Pattern.compile("^\\[INFO] Building .*\\[(\\d+)/(\\d+)]\\s*$");
    private static final Pattern INSTALL_GOAL = Pattern.compile("^\\[INFO] --- (?:maven-)?install(?:-plugin)?:\\S+:install .*@ (\\S+) ---");
    private static final Pattern INSTALLING = Pattern.compile("^\\[INFO] Installing (.+) to (.+)$");
    private static final Pattern BOUNDARY = Pattern.compile("^\\[INFO] (?:--- |Building |Reactor Summary|BUILD )");

    /** One module's installed files. */
    record Installed(String artifactId, String position, List<Path> files) {
        /** jar, pom, sources, javadoc, tests: what kinds of file were installed. */
        Set<String> kinds() {
            Set<String> kinds = new LinkedHashSet<>();
            for (Path file : files) {
                String name = file.getFileName().toString();
                kinds.add(name.endsWith("-sources.jar") ? "sources" : name.endsWith("-javadoc.jar") ? "javadoc"
                        : name.endsWith("-tests.jar") ? "tests" : name.substring(name.lastIndexOf('.') + 1));
            }
            return kinds;
        }
    }

    private final Consumer<Installed> onModule;
    private final List<Installed> installed = new ArrayList<>();
    private String position = "";
    private String current;
    private List<Path> files = new ArrayList<>();

    InstallProgress(Consumer<Installed> onModule) {
        this.onModule = onModule;
    }

    @Override
    public void accept(String line) {
        Matcher installing = INSTALLING.matcher(line);
        if (current != null && installing.matches()) {
            files.add(Path.of(installing.group(2).trim()));
            return;
        }
        if (BOUNDARY.matcher(line).find()) {
            finishModule();
        }
        Matcher building = BUILDING.matcher(line);
        if (building.matches()) {
            position = "[" + building.group(1) + "/" + building.group(2) + "]";
        }
        Matcher goal = INSTALL_GOAL.matcher(line);
        if (goal.find()) {
            current = goal.group(1);
            files = new ArrayList<>();
        }
    }

    /** Ends the module whose files were being listed (at the end of Maven's output too). */
    void finishModule() {
        if (current != null && !files.isEmpty()) {
            Installed module = new Installed(current, position, List.copyOf(files));
            installed.add(module);
            onModule.accept(module);
        }
        current = null;
    }

    List<Installed> installed() {
        return List.copyOf(installed);
    }

    /** The folder every installed file lies under (the local repository's org/fdnet), or null when none was. */
    Path commonFolder() {
        Path common = null;
        for (Installed module : installed) {
            for (Path file : module.files()) {
                Path folder = file.getParent();
                if (common == null) {
                    common = folder;
                }
                while (common != null && !folder.startsWith(common)) {
                    common = common.getParent();
                }
            }
        }
        return common;
    }
}
