package org.fdnet.docs;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * Documents and sources describe the system as it is: no text names a work session or an issue number (that story
 * belongs in the commit messages). Covers README.md, docs/, CHANGELOG.md and every module's src.
 */
class NoWorkHistoryTest {
    private static final Pattern HISTORY = Pattern.compile("(?i)session [0-9]|issue #[0-9]");

    @Test
    void shouldNameNoWorkSessionOrIssueInDocumentsOrSources() throws IOException {
        List<String> found = new ArrayList<>();
        List<Path> files = new ArrayList<>(ProjectFiles.documents());
        try (Stream<Path> all = Files.walk(ProjectFiles.ROOT)) {
            all.filter(p -> p.toString().contains("/src/") && !p.toString().contains("/target/")
                            && !p.toString().contains("/.git/") && Files.isRegularFile(p)
                            && p.toString().matches(".*\\.(java|c|h|md|properties|xml|fdn|txt)$"))
                    .forEach(files::add);
        }
        for (Path file : files) {
            String[] lines = ProjectFiles.read(file).split("\n", -1);
            for (int i = 0; i < lines.length; i++) {
                if (HISTORY.matcher(lines[i]).find()) {
                    found.add(ProjectFiles.relative(file) + ":" + (i + 1) + ": " + lines[i].strip());
                }
            }
        }
        assertThat(found).as("lines that tell the project's history").isEmpty();
    }
}
