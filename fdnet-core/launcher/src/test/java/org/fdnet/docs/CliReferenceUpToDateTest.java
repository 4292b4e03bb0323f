package org.fdnet.docs;

import static org.assertj.core.api.Assertions.assertThat;

import org.fdnet.cli.CliReference;
import org.fdnet.cli.FdnetCommand;
import org.junit.jupiter.api.Test;

/**
 * The committed command-line reference and the README's command table are what the whole command tree (every module,
 * benches included, as bin/fdnet runs it) generates: a changed option or description fails the build until
 * {@code bin/fdnet reference --write} is run and its result committed.
 */
class CliReferenceUpToDateTest {
    private static final String FIX = " is out of date: run bin/fdnet reference --write and commit the result";
    private final CliReference reference = new CliReference(FdnetCommand.commandLine());

    @Test
    void shouldMatchTheCommittedReferencePage() {
        assertThat(ProjectFiles.read(ProjectFiles.ROOT.resolve(CliReference.PAGE)))
                .as(CliReference.PAGE + FIX).isEqualTo(reference.page());
    }

    @Test
    void shouldMatchTheReadmesCommandTable() {
        String readme = ProjectFiles.read(ProjectFiles.ROOT.resolve("README.md"));
        assertThat(readme).as("README.md's command table" + FIX).isEqualTo(reference.withReadmeTable(readme));
    }
}
