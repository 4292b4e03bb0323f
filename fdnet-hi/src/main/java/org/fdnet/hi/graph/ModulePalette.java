package org.fdnet.hi.graph;

import java.awt.Color;
import java.util.Locale;

/** Colours for modules that have none in the .fdg, and the light tint nodes are filled with. */
public final class ModulePalette {
    private static final Color[] COLOURS = {
        new Color(0x4A6FA5), new Color(0x3C9D5D), new Color(0xD9822B), new Color(0x8E5BA8),
        new Color(0xC0392B), new Color(0x16A085), new Color(0x7F8C8D), new Color(0xB7950B),
    };

    private ModulePalette() {
    }

    static Color colourFor(int index) {
        return COLOURS[Math.floorMod(index, COLOURS.length)];
    }

    static Color tint(Color c) {
        return new Color(mix(c.getRed()), mix(c.getGreen()), mix(c.getBlue()));
    }

    private static int mix(int v) {
        return (int) Math.round(v * 0.25 + 255 * 0.75);
    }

    /** {@code #RRGGBB}, the .fdg form. */
    public static String hex(Color c) {
        return String.format(Locale.ROOT, "#%02X%02X%02X", c.getRed(), c.getGreen(), c.getBlue());
    }
}
