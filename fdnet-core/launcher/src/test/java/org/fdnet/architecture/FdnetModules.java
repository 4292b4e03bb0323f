package org.fdnet.architecture;

import com.tngtech.archunit.base.DescribedPredicate;
import com.tngtech.archunit.core.domain.JavaClass;
import com.tngtech.archunit.core.importer.ImportOption;
import com.tngtech.archunit.core.importer.Location;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Which Maven module owns a class, by its package. No package name is split across two modules, so the package
 * alone says it: each module owns the package trees listed in {@link #PACKAGE_TREES}, and the most specific tree
 * wins ({@code org.fdnet.runtime} is the node API in {@code fdnet-core/api}, {@code org.fdnet.runtime.engine} the
 * engine in {@code fdnet-core}).
 *
 * <p>{@link #builtBy} reads where a class was actually loaded from ({@code …/fdnet-core/api/target/classes/…} in
 * a {@code mvn test}, {@code …/fdnet-api-….jar!/…} in a {@code mvn verify} or from the local repository): the
 * architecture test compares the two, so a package that appears in a second module fails the build instead of
 * blurring the layers.
 */
final class FdnetModules {
    /** Module folder → the package trees it owns (a tree is a package and its sub-packages). */
    static final Map<String, List<String>> PACKAGE_TREES = packageTrees();

    private static final Pattern FOLDER = Pattern.compile(
            "/((?:fdnet-core|fdnet-logger|fdnet-viewer|fdnet-hi|roq-sim)(?:/[a-z]+)?)/target/");
    private static final Pattern ARTIFACT = Pattern.compile("/org/fdnet/([a-z-]+)/[^/]+/\\1-[^/]*\\.jar");
    /** Artifact ids whose folder is not the artifact id itself. */
    private static final Map<String, String> FOLDER_OF_ARTIFACT = Map.of(
            "fdnet-api", "fdnet-core/api", "fdnet-core-bench", "fdnet-core/bench",
            "fdnet-logger-bench", "fdnet-logger/bench", "fdnet-viewer-bench", "fdnet-viewer/bench",
            "fdnet-hi-bench", "fdnet-hi/bench", "roq-sim-bench", "roq-sim/bench", "fdnet-launcher", "fdnet-core/launcher",
            "fdnet-testkit", "fdnet-core/testkit", "roq-testkit", "roq-sim/testkit");

    /** Test classes and test jars are not the product: the architecture is that of the main code. */
    static final ImportOption MAIN_CODE_ONLY = (Location location) ->
            !location.contains("/test-classes/") && !location.matches(Pattern.compile(".*-tests\\.jar.*"));

    private FdnetModules() {
    }

    private static Map<String, List<String>> packageTrees() {
        Map<String, List<String>> trees = new LinkedHashMap<>();
        trees.put("fdnet-core/api", List.of("org.fdnet.cli.spi", "org.fdnet.event", "org.fdnet.layout",
                "org.fdnet.netinfo", "org.fdnet.runtime", "org.fdnet.tls"));
        trees.put("fdnet-core", List.of("org.fdnet.apart", "org.fdnet.cli", "org.fdnet.control", "org.fdnet.corba",
                "org.fdnet.logging", "org.fdnet.netinfo.xml", "org.fdnet.run", "org.fdnet.runtime.cli",
                "org.fdnet.runtime.engine", "org.fdnet.runtime.library", "org.fdnet.runtime.loading"));
        trees.put("fdnet-logger", List.of("org.fdnet.logger"));
        trees.put("fdnet-viewer", List.of("org.fdnet.viewer"));
        trees.put("fdnet-hi", List.of("org.fdnet.hi"));
        trees.put("roq-sim", List.of("org.fdnet.roq"));
        trees.put("fdnet-core/testkit", List.of("org.fdnet.testkit"));
        trees.put("roq-sim/testkit", List.of("org.fdnet.roq.testkit"));
        trees.put("fdnet-core/bench", List.of("org.fdnet.bench", "org.fdnet.corba.bench", "org.fdnet.runtime.bench"));
        trees.put("fdnet-logger/bench", List.of("org.fdnet.logger.bench", "org.fdnet.logger.soak"));
        trees.put("fdnet-viewer/bench", List.of("org.fdnet.viewer.bench"));
        trees.put("fdnet-hi/bench", List.of("org.fdnet.hi.bench"));
        trees.put("roq-sim/bench", List.of("org.fdnet.roq.bench"));
        return trees;
    }

    /** The module folder that owns {@code packageName} (e.g. {@code fdnet-core/api}); empty when none does. */
    static String ownerOf(String packageName) {
        return PACKAGE_TREES.entrySet().stream()
                .flatMap(e -> e.getValue().stream()
                        .filter(tree -> packageName.equals(tree) || packageName.startsWith(tree + "."))
                        .map(tree -> Map.entry(tree, e.getKey())))
                .max(Comparator.comparingInt(e -> e.getKey().length()))
                .map(Map.Entry::getValue)
                .orElse("");
    }

    /** The module folder that owns {@code type}'s package. */
    static String moduleOf(JavaClass type) {
        return ownerOf(type.getPackageName());
    }

    /** The module folder {@code type} was loaded from, when its location tells (class folder or artifact jar). */
    static Optional<String> builtBy(JavaClass type) {
        return type.getSource().map(source -> {
            String uri = source.getUri().toString();
            Matcher m = FOLDER.matcher(uri);
            if (m.find()) {
                return m.group(1);
            }
            Matcher a = ARTIFACT.matcher(uri);
            return a.find() ? FOLDER_OF_ARTIFACT.getOrDefault(a.group(1), a.group(1)) : "";
        }).filter(folder -> !folder.isEmpty());
    }

    /** Classes of the module in folder {@code folder}. */
    static DescribedPredicate<JavaClass> inModule(String folder) {
        return DescribedPredicate.describe("in module " + folder, type -> moduleOf(type).equals(folder));
    }

    /** Classes of a bench module ({@code fdnet-core/bench}, {@code roq-sim/bench}, …): benchmarks and rigs. */
    static DescribedPredicate<JavaClass> inABenchModule() {
        return DescribedPredicate.describe("in a bench module", type -> moduleOf(type).endsWith("/bench"));
    }

    /** Classes of module {@code folder} in one of {@code packages} (ArchUnit package patterns). */
    static DescribedPredicate<JavaClass> inModulePackages(String folder, String... packages) {
        return DescribedPredicate.describe("in module " + folder + " " + String.join(", ", packages),
                type -> moduleOf(type).equals(folder) && JavaClass.Predicates.resideInAnyPackage(packages).test(type));
    }
}
