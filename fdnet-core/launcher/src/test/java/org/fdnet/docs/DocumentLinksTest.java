package org.fdnet.docs;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * Every relative link in the README, the changelog and docs/ leads somewhere: the file exists and, when the link names
 * a heading ({@code page.md#heading}), the page has that heading; and every page that code, networks, scripts and POMs
 * name ({@code docs/…/page.md}) exists. Links to the web are not followed (the build runs offline).
 */
class DocumentLinksTest {
    /** {@code [text](target)} and {@code ![alt](target)}; the target ends at a space (a title) or the bracket. */
    private static final Pattern LINK = Pattern.compile("\\]\\(([^)\\s]+)(?:\\s+\"[^\"]*\")?\\)");
    private static final Pattern HEADING = Pattern.compile("(?m)^#{1,6}\\s+(.+?)\\s*#*\\s*$");
    private static final Pattern FENCE = Pattern.compile("(?ms)^```.*?^```");
    /** A page path as code and networks name it, e.g. {@code docs/reference/protocol.md}. */
    private static final Pattern DOCS_PATH = Pattern.compile("docs/[A-Za-z0-9_/.-]+\\.md");

    @Test
    void shouldResolveEveryRelativeLinkInTheDocuments() {
        List<String> broken = new ArrayList<>();
        for (Path doc : ProjectFiles.documents()) {
            String text = FENCE.matcher(ProjectFiles.read(doc)).replaceAll("");
            Matcher m = LINK.matcher(text);
            while (m.find()) {
                String problem = problem(doc, m.group(1));
                if (problem != null) {
                    broken.add(ProjectFiles.relative(doc) + ": " + m.group(1) + ": " + problem);
                }
            }
        }
        assertThat(broken).as("links that lead nowhere").isEmpty();
    }

    @Test
    void shouldNameOnlyPagesThatExistWhereCodeAndNetworksPointIntoTheDocuments() throws IOException {
        List<String> missing = new ArrayList<>();
        try (Stream<Path> files = Files.walk(ProjectFiles.ROOT)) {
            for (Path file : files.filter(DocumentLinksTest::pointsIntoDocs).toList()) {
                // ISO-8859-1 reads any file (a network may be in Shift_JIS); the paths looked for are ASCII
                Matcher m = DOCS_PATH.matcher(new String(Files.readAllBytes(file), StandardCharsets.ISO_8859_1));
                while (m.find()) {
                    if (!Files.exists(ProjectFiles.ROOT.resolve(m.group()))) {
                        missing.add(ProjectFiles.relative(file) + ": " + m.group());
                    }
                }
            }
        }
        assertThat(missing).as("pages named in code, networks, scripts and POMs that do not exist").isEmpty();
    }

    private static boolean pointsIntoDocs(Path p) {
        String s = p.toString();
        return Files.isRegularFile(p) && !s.contains("/target/") && !s.contains("/.git/")
                && (s.contains("/src/") && s.matches(".*\\.(java|c|h|properties)$") || s.endsWith(".fdn")
                        || s.endsWith("pom.xml") || s.contains("/bin/") || s.contains("/.ci/"));
    }

    @Test
    void shouldFindAHeadingsAnchorTheWayGitHubSpellsIt() {
        assertThat(anchor("Live changes across hosts")).isEqualTo("live-changes-across-hosts");
        assertThat(anchor("Mutual TLS and the threat model")).isEqualTo("mutual-tls-and-the-threat-model");
        assertThat(anchor("`fdnet bench load` — files, cold")).isEqualTo("fdnet-bench-load--files-cold");
    }

    private static String problem(Path doc, String target) {
        if (target.matches("^[a-z][a-z0-9+.-]*:.*")) {
            return null; // http:, https:, mailto: — not followed offline
        }
        int hash = target.indexOf('#');
        String file = hash < 0 ? target : target.substring(0, hash);
        Path resolved = file.isEmpty() ? doc : doc.getParent().resolve(file).normalize();
        if (!Files.exists(resolved)) {
            return "no such file " + ProjectFiles.relative(resolved);
        }
        if (hash < 0 || !resolved.toString().endsWith(".md")) {
            return null;
        }
        String wanted = target.substring(hash + 1);
        return anchors(resolved).contains(wanted) ? null : "no heading with anchor #" + wanted + " in " + ProjectFiles.relative(resolved);
    }

    private static Set<String> anchors(Path page) {
        String text = FENCE.matcher(ProjectFiles.read(page)).replaceAll("");
        Matcher m = HEADING.matcher(text);
        List<String> found = new ArrayList<>();
        while (m.find()) {
            String a = anchor(m.group(1));
            long before = found.stream().filter(x -> x.equals(a)).count();
            found.add(a);
            if (before > 0) {
                found.add(a + "-" + before); // GitHub numbers repeated headings
            }
        }
        return found.stream().collect(Collectors.toSet());
    }

    /** GitHub's rule: lower case, punctuation dropped (hyphens and underscores kept), spaces become hyphens. */
    static String anchor(String heading) {
        return heading.toLowerCase(Locale.ROOT).replaceAll("[^\\p{L}\\p{N} _-]", "").replace(' ', '-');
    }
}
