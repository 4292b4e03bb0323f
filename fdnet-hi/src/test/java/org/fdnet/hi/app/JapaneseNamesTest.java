package org.fdnet.hi.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.Font;
import java.nio.charset.Charset;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.fdnet.hi.graph.Java2DSketch;
import org.fdnet.viewer.legible.LegibleFont;
import org.junit.jupiter.api.Test;

/**
 * The thesis lab's kind of network — Japanese names in an EUC-JP file — opens with every name intact and drawn
 * in a font that has their characters; a font without them is refused with the package to install.
 */
class JapaneseNamesTest {
    private static final Path ARMS_JA = Path.of("..", "networks", "arms-ja.fdn");

    @Test
    void shouldOpenAnEucJpNetworkAndPickAFontThatDisplaysEveryName() throws Exception {
        assertThat(Files.readString(ARMS_JA, Charset.forName("EUC-JP"))).startsWith("<?xml version=\"1.0\" encoding=\"EUC-JP\"?>");
        OpenNetwork open = OpenNetwork.load(ARMS_JA);
        List<String> names = NamesFont.of(open.editor().network());
        assertThat(names).contains("両腕", "時計", "心拍", "到達意図", "左腕", "右腕", "肩目標", "サーボ", "鏡像");

        LegibleFont.Choice choice = NamesFont.forGraph(open.editor().network());
        assertThat(choice.warning()).as("a CJK font is installed (bin/fdnet and .ci/run install %s as root)",
                LegibleFont.PACKAGE).isNull();
        for (String name : names) {
            assertThat(choice.font().canDisplayUpTo(name)).as("%s displayable in %s", name, choice.font().getFamily())
                    .isEqualTo(-1);
        }
        assertThat(choice.font().getSize()).isEqualTo(Java2DSketch.PLAIN.getSize());
    }

    @Test
    void shouldNameThePackageToInstallWhenNoFontDisplaysAName() {
        // U+E000 is in the Private Use Area: no installed font has a glyph for it.
        String undisplayable = "\uE000\uE001";
        LegibleFont.Choice choice = LegibleFont.forNames(new Font(Font.SANS_SERIF, Font.PLAIN, 12),
                List.of("Clock", undisplayable));
        assertThat(choice.legible()).isFalse();
        assertThat(choice.warning()).contains("1 name cannot be shown", undisplayable,
                "sudo apt-get install -y fonts-noto-cjk");
    }
}
