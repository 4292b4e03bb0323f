package org.fdnet.architecture;

import static com.tngtech.archunit.base.DescribedPredicate.not;
import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses;
import static com.tngtech.archunit.library.Architectures.layeredArchitecture;
import static com.tngtech.archunit.library.dependencies.SlicesRuleDefinition.slices;
import static org.assertj.core.api.Assertions.assertThat;
import static org.fdnet.architecture.FdnetModules.inABenchModule;
import static org.fdnet.architecture.FdnetModules.inModule;
import static org.fdnet.architecture.FdnetModules.inModulePackages;

import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import com.tngtech.archunit.lang.ArchRule;
import java.util.List;
import java.util.Set;
import java.util.stream.Collectors;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * The architecture docs/explanation/architecture.md draws, checked on the main code of every module (benchmarks included):
 * no package cycle anywhere, and every import along the layering. A change that breaks either fails
 * {@code mvn -B verify}; change the drawing and this test together.
 */
class ArchitectureTest {
    private static final String CORE = "fdnet-core";
    private static JavaClasses classes;

    @BeforeAll
    static void importEveryModule() {
        classes = new ClassFileImporter().withImportOption(FdnetModules.MAIN_CODE_ONLY).importPackages("org.fdnet");
    }

    @Test
    void shouldSeeTheMainCodeOfEveryModule() {
        Set<String> modules = classes.stream().map(FdnetModules::moduleOf).collect(Collectors.toSet());
        assertThat(modules).contains("fdnet-core/api", CORE, "fdnet-logger", "fdnet-viewer", "fdnet-hi", "roq-sim",
                "fdnet-core/bench", "fdnet-logger/bench", "fdnet-viewer/bench", "fdnet-hi/bench", "roq-sim/bench",
                "fdnet-core/testkit", "roq-sim/testkit");
        assertThat(modules).doesNotContain("");
    }

    @Test
    void shouldKeepEveryPackageInTheOneModuleThatOwnsIt() {
        List<String> misplaced = classes.stream()
                .filter(type -> FdnetModules.builtBy(type).filter(folder -> !folder.equals(FdnetModules.moduleOf(type)))
                        .isPresent())
                .map(type -> type.getName() + " is built by " + FdnetModules.builtBy(type).orElseThrow()
                        + " but its package belongs to " + FdnetModules.moduleOf(type))
                .distinct().sorted().toList();
        assertThat(misplaced).as("classes outside the module that owns their package (a split package)").isEmpty();
    }

    @Test
    void shouldHaveNoPackageCycle() {
        slices().matching("org.fdnet.(**)").namingSlices("$1")
                .should().beFreeOfCycles()
                .check(classes);
    }

    @Test
    void shouldImportOnlyDownTheLayers() {
        layers().check(classes);
    }

    @Test
    void shouldKeepCorbaXmlAndTheEngineOutOfTheApiTheLoggerAndTheViewer() {
        noClasses().that(inModule("fdnet-core/api")).or(inModule("fdnet-logger")).or(inModule("fdnet-viewer"))
                .should().dependOnClassesThat().resideInAnyPackage("org.omg..", "org.jacorb..", "jakarta.xml.bind..")
                .check(classes);
    }

    @Test
    void shouldUseHdrHistogramInBenchModulesOnly() {
        noClasses().that(not(inABenchModule()))
                .should().dependOnClassesThat().resideInAPackage("org.HdrHistogram..")
                .check(classes);
    }

    /** The layering of docs/explanation/architecture.md, bottom first. A layer may use the ones its line names. */
    static ArchRule layers() {
        return layeredArchitecture().consideringOnlyDependenciesInLayers()
                .layer("Api").definedBy(inModule("fdnet-core/api").and(not(inModulePackages("fdnet-core/api",
                        "org.fdnet.runtime"))))
                .layer("Files").definedBy(inModulePackages(CORE, "org.fdnet.netinfo.xml..", "org.fdnet.logging"))
                .layer("Runtime API").definedBy(inModulePackages("fdnet-core/api", "org.fdnet.runtime"))
                .layer("Nodes").definedBy(inModulePackages(CORE, "org.fdnet.runtime.library"))
                .layer("Engine").definedBy(inModulePackages(CORE, "org.fdnet.runtime.engine",
                        "org.fdnet.runtime.loading"))
                .layer("Control").definedBy(inModulePackages(CORE, "org.fdnet.control"))
                .layer("Distribution").definedBy(inModulePackages(CORE, "org.fdnet.corba", "org.fdnet.corba.control",
                        "org.fdnet.corba.idl"))
                .layer("Commands").definedBy(inModulePackages(CORE, "org.fdnet.cli", "org.fdnet.corba.cli",
                        "org.fdnet.runtime.cli", "org.fdnet.run"))
                .layer("Logger").definedBy(inModule("fdnet-logger"))
                .layer("Viewer").definedBy(inModule("fdnet-viewer"))
                .layer("Editor").definedBy(inModule("fdnet-hi"))
                .layer("Simulator").definedBy(inModule("roq-sim"))
                .layer("Test kit").definedBy(inModule("fdnet-core/testkit"))
                .layer("Robot test kit").definedBy(inModule("roq-sim/testkit"))
                .layer("Bench").definedBy(inABenchModule())

                .whereLayer("Api").mayNotAccessAnyLayer()
                .whereLayer("Files").mayOnlyAccessLayers("Api")
                .whereLayer("Runtime API").mayOnlyAccessLayers("Api")
                .whereLayer("Nodes").mayOnlyAccessLayers("Api", "Runtime API")
                .whereLayer("Engine").mayOnlyAccessLayers("Api", "Runtime API")
                .whereLayer("Control").mayOnlyAccessLayers("Api", "Runtime API")
                .whereLayer("Distribution").mayOnlyAccessLayers("Api", "Files", "Runtime API", "Nodes", "Engine",
                        "Control")
                .whereLayer("Commands").mayOnlyAccessLayers("Api", "Files", "Runtime API", "Nodes", "Engine", "Control",
                        "Distribution")
                .whereLayer("Logger").mayOnlyAccessLayers("Api")
                .whereLayer("Viewer").mayOnlyAccessLayers("Api", "Logger") // Export…: the logger's MCAP and CSV writers
                .whereLayer("Editor").mayOnlyAccessLayers("Api", "Files", "Runtime API", "Nodes", "Engine", "Control",
                        "Distribution", "Commands", "Viewer")
                .whereLayer("Simulator").mayOnlyAccessLayers("Api", "Files", "Runtime API", "Nodes", "Engine",
                        "Control", "Distribution", "Commands", "Logger", "Viewer")
                .whereLayer("Test kit").mayOnlyAccessLayers("Api", "Files", "Runtime API", "Nodes", "Engine")
                .whereLayer("Robot test kit").mayOnlyAccessLayers("Api", "Files", "Runtime API", "Nodes", "Engine",
                        "Logger", "Simulator", "Test kit")
                .whereLayer("Test kit").mayOnlyBeAccessedByLayers("Robot test kit", "Bench")
                .whereLayer("Robot test kit").mayOnlyBeAccessedByLayers("Bench")
                .whereLayer("Bench").mayNotBeAccessedByAnyLayer();
    }
}
