package org.fdnet.viewer.legible;

import java.awt.Font;
import java.awt.GraphicsEnvironment;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;

/**
 * Picks a font that can draw every name a window shows. The logical fonts (SansSerif, Dialog) already fall
 * back to any installed CJK font through fontconfig, so usually the preferred font is kept; when it cannot
 * draw a name, the first installed family that can draw them all is taken (known CJK families first); when
 * none can, the preferred font stays and {@link Choice#warning()} says which name cannot be shown and the
 * Debian package that fixes it.
 */
public final class LegibleFont {
    /** The Debian package bin/fdnet and .ci/run install as root; named in the warning. */
    public static final String PACKAGE = "fonts-noto-cjk";
    private static final List<String> KNOWN_FAMILIES = List.of("Noto Sans CJK JP", "IPAGothic", "IPAPGothic",
            "Noto Sans Mono CJK JP", "Noto Serif CJK JP", "VL Gothic", "TakaoGothic");

    private LegibleFont() {
    }

    /** The font to use, and a warning for the status bar when no installed font draws every name (else null). */
    public record Choice(Font font, String warning) {
        public boolean legible() {
            return warning == null;
        }
    }

    /** A font with the style and size of {@code preferred} that draws every one of {@code names}. */
    public static Choice forNames(Font preferred, Collection<String> names) {
        String all = String.join("\n", names);
        if (preferred.canDisplayUpTo(all) == -1) {
            return new Choice(preferred, null);
        }
        for (String family : candidates()) {
            Font f = new Font(family, preferred.getStyle(), preferred.getSize()).deriveFont(preferred.getSize2D());
            if (f.canDisplayUpTo(all) == -1) {
                return new Choice(f, null);
            }
        }
        return new Choice(preferred, warning(preferred, names));
    }

    private static List<String> candidates() {
        List<String> out = new ArrayList<>(KNOWN_FAMILIES);
        for (String family : GraphicsEnvironment.getLocalGraphicsEnvironment().getAvailableFontFamilyNames()) {
            if (!out.contains(family)) {
                out.add(family);
            }
        }
        return out;
    }

    private static String warning(Font preferred, Collection<String> names) {
        String example = names.stream().filter(n -> preferred.canDisplayUpTo(n) != -1).findFirst().orElse("?");
        long count = names.stream().filter(n -> preferred.canDisplayUpTo(n) != -1).count();
        return String.format("%d name%s cannot be shown (e.g. \"%s\"): no installed font has their characters;"
                + " install one: sudo apt-get install -y %s", count, count == 1 ? "" : "s", example, PACKAGE);
    }
}
