package org.fdnet.cli;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

class CliReferenceTest {
    @Command(name = "tool", mixinStandardHelpOptions = true, description = "The tool | its root.",
            subcommands = {Zeta.class, Alpha.class, Secret.class})
    static final class Tool implements Runnable {
        @Override
        public void run() {
        }
    }

    @Command(name = "zeta", description = {"Zeta does the last thing, e.g. this,", "over two lines. More about zeta."})
    static final class Zeta implements Runnable {
        @Option(names = "--for", defaultValue = "5s", description = "how long (default ${DEFAULT-VALUE})")
        String duration;

        @Override
        public void run() {
        }
    }

    @Command(name = "alpha", description = "Alpha does the first thing.", subcommands = Inner.class)
    static final class Alpha implements Runnable {
        @Override
        public void run() {
        }
    }

    @Command(name = "inner", description = "Inside alpha.")
    static final class Inner implements Runnable {
        @Override
        public void run() {
        }
    }

    @Command(name = "secret", hidden = true, description = "Not for the reference.")
    static final class Secret implements Runnable {
        @Override
        public void run() {
        }
    }

    private final CliReference reference = new CliReference(new CommandLine(new Tool()));

    @Test
    void shouldListEveryVisibleCommandInNameOrderWithItsFirstDescriptionLine() {
        assertThat(reference.page()).contains("| [`tool alpha`](#tool-alpha) | Alpha does the first thing. |\n"
                        + "| [`tool alpha inner`](#tool-alpha-inner) | Inside alpha. |\n"
                        + "| [`tool zeta`](#tool-zeta) | Zeta does the last thing, e.g. this, over two lines. |\n")
                .contains("| [`tool`](#tool) | The tool \\| its root. |")
                .doesNotContain("secret");
    }

    @Test
    void shouldGiveEachCommandItsHelpTextWithDefaultsFilledIn() {
        assertThat(reference.page()).contains("## tool zeta\n\n```\nUsage: tool zeta [--for=<duration>]")
                .contains("how long (default 5s)").contains("More about zeta.");
    }

    @Test
    void shouldReplaceOnlyTheReadmesGeneratedTable() {
        String readme = "# Tool\n\nintro\n\n" + CliReference.TABLE_START + "\nold table\n" + CliReference.TABLE_END
                + "\n\nafter\n";
        String updated = reference.withReadmeTable(readme);
        assertThat(updated).startsWith("# Tool\n\nintro\n\n" + CliReference.TABLE_START + "\n| command | what it does |")
                .contains("| [`tool alpha`](docs/reference/cli.md#tool-alpha) | Alpha does the first thing. |")
                .doesNotContain("old table").doesNotContain("tool alpha inner")
                .endsWith(CliReference.TABLE_END + "\n\nafter\n");
        assertThat(reference.withReadmeTable(updated)).isEqualTo(updated);
    }

    @Test
    void shouldNameTheMissingMarkersWhenTheReadmeHasNoTable() {
        assertThatThrownBy(() -> reference.withReadmeTable("# Tool\n")).isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining(CliReference.TABLE_START);
    }
}
