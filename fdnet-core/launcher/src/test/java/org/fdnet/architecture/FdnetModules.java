package org.fdnet.architecture;

import com.tngtech.archunit.base.DescribedPredicate;
import com.tngtech.archunit.core.domain.JavaClass;
import com.tngtech.archunit.core.importer.ImportOption;
import com.tngtech.archunit.core.importer.Location;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Which Maven module a class was built by, read from where it was loaded: {@code …/fdnet-core/api/target/classes/…}
 * in a {@code mvn test}, {@code …/fdnet-core/api/target/fdnet-api-….jar!/…} in a {@code mvn verify}: the module is
 * the folder before {@code /target/}, relative to the project root ({@code fdnet-core/api}, {@code roq-sim/bench}).
 * A module taken from the local repository (a {@code mvn -pl fdnet-core/launcher test}) is found by its artifact
 * ({@code …/org/fdnet/fdnet-api/…}), so the test says the same however it is started.
 */
final class FdnetModules {
    private static final Pattern MODULE = Pattern.compile(
            "/((?:fdnet-core|fdnet-logger|fdnet-viewer|fdnet-hi|roq-sim)(?:/[a-z]+)?)/target/");
    private static final Pattern ARTIFACT = Pattern.compile("/org/fdnet/([a-z-]+)/[^/]+/\\1-[^/]*\\.jar");
    /** Artifact ids whose folder is not the artifact id itself. */
    private static final Map<String, String> FOLDER_OF_ARTIFACT = Map.of(
            "fdnet-api", "fdnet-core/api", "fdnet-core-bench", "fdnet-core/bench",
            "fdnet-logger-bench", "fdnet-logger/bench", "fdnet-viewer-bench", "fdnet-viewer/bench",
            "fdnet-hi-bench", "fdnet-hi/bench", "roq-sim-bench", "roq-sim/bench", "fdnet-launcher", "fdnet-core/launcher");

    /** Test classes and test jars are not the product: the architecture is that of the main code. */
    static final ImportOption MAIN_CODE_ONLY = (Location location) ->
            !location.contains("/test-classes/") && !location.matches(Pattern.compile(".*-tests\\.jar.*"));

    private FdnetModules() {
    }

    /** The module folder of {@code type}, e.g. {@code fdnet-core/api}; empty when it came from no module. */
    static String moduleOf(JavaClass type) {
        return type.getSource()
                .map(source -> {
                    String uri = source.getUri().toString();
                    Matcher m = MODULE.matcher(uri);
                    if (m.find()) {
                        return m.group(1);
                    }
                    Matcher a = ARTIFACT.matcher(uri);
                    return a.find() ? FOLDER_OF_ARTIFACT.getOrDefault(a.group(1), a.group(1)) : "";
                })
                .orElse("");
    }

    /** Classes built by the module in folder {@code folder}. */
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
                type -> moduleOf(type).equals(folder) && type.getPackage().getName() != null
                        && JavaClass.Predicates.resideInAnyPackage(packages).test(type));
    }
}
