package org.fdnet.netinfo.xml;

import java.io.ByteArrayInputStream;
import java.io.StringReader;
import java.nio.charset.Charset;
import java.nio.charset.StandardCharsets;
import org.xml.sax.InputSource;

/**
 * Makes sure the parser sees a DOCTYPE, so that a file without one is validated too (the JDK's
 * parser never asks {@code EntityResolver2.getExternalSubset}). When the prolog has no DOCTYPE, one
 * naming the bundled DTD is inserted right before the root element, on the same line; positions on
 * that line are shifted back by {@link #correctColumn}. The inserted DOCTYPE is ASCII, so for every
 * ASCII-compatible encoding (UTF-8, EUC-JP, Shift_JIS, ISO-8859-x) the bytes are spliced and the
 * file's own encoding declaration still rules; UTF-16 files are decoded first.
 */
final class DoctypeSupplier {
    static final String INSERTED_SYSTEM_ID = "fdnet-bundled.dtd";

    private final InputSource source;
    private final boolean inserted;
    private final int line;
    private final int column;
    private final int length;

    private DoctypeSupplier(InputSource source, boolean inserted, int line, int column, int length) {
        this.source = source;
        this.inserted = inserted;
        this.line = line;
        this.column = column;
        this.length = length;
    }

    static DoctypeSupplier prepare(byte[] content, BundledDtd dtd) {
        Charset utf16 = utf16(content);
        String prolog = utf16 != null ? new String(content, utf16) : new String(content, StandardCharsets.ISO_8859_1);
        int root = rootElementStart(prolog);
        if (root < 0) {
            return new DoctypeSupplier(new InputSource(new ByteArrayInputStream(content)), false, 0, 0, 0);
        }
        String doctype = "<!DOCTYPE " + dtd.root() + " SYSTEM \"" + INSERTED_SYSTEM_ID + "\">";
        int line = 1;
        int lineStart = 0;
        for (int i = 0; i < root; i++) {
            if (prolog.charAt(i) == '\n') {
                line++;
                lineStart = i + 1;
            }
        }
        int column = root - lineStart + 1;
        if (utf16 != null) {
            String text = prolog.substring(0, root) + doctype + prolog.substring(root);
            return new DoctypeSupplier(new InputSource(new StringReader(stripDeclaration(text))), true, line, column, doctype.length());
        }
        byte[] spliced = new byte[content.length + doctype.length()];
        System.arraycopy(content, 0, spliced, 0, root);
        System.arraycopy(doctype.getBytes(StandardCharsets.US_ASCII), 0, spliced, root, doctype.length());
        System.arraycopy(content, root, spliced, root + doctype.length(), content.length - root);
        return new DoctypeSupplier(new InputSource(new ByteArrayInputStream(spliced)), true, line, column, doctype.length());
    }

    InputSource source() {
        return source;
    }

    /** Whether the DOCTYPE the parser reports is ours rather than the file's. */
    boolean inserted() {
        return inserted;
    }

    /** The column as the file has it, for a position the parser reported in the spliced text. */
    int correctColumn(int reportedLine, int reportedColumn) {
        if (inserted && reportedLine == line && reportedColumn > column) {
            return Math.max(column, reportedColumn - length);
        }
        return reportedColumn;
    }

    /**
     * The offset of the root element's '<' when the prolog has no DOCTYPE, or -1 when it has one
     * (or the text is not XML enough to tell: the parser will then say what is wrong).
     */
    private static int rootElementStart(String text) {
        int i = text.isEmpty() || text.charAt(0) != '\uFEFF' ? 0 : 1;
        while (i < text.length()) {
            char c = text.charAt(i);
            if (Character.isWhitespace(c)) {
                i++;
            } else if (text.startsWith("<?", i)) {
                int end = text.indexOf("?>", i);
                if (end < 0) {
                    return -1;
                }
                i = end + 2;
            } else if (text.startsWith("<!--", i)) {
                int end = text.indexOf("-->", i);
                if (end < 0) {
                    return -1;
                }
                i = end + 3;
            } else if (c == '<' && i + 1 < text.length() && text.charAt(i + 1) != '!') {
                return i;
            } else {
                return -1;
            }
        }
        return -1;
    }

    private static Charset utf16(byte[] b) {
        if (b.length >= 2 && ((b[0] == (byte) 0xFE && b[1] == (byte) 0xFF) || (b[0] == 0 && b[1] == '<'))) {
            return StandardCharsets.UTF_16BE;
        }
        if (b.length >= 2 && ((b[0] == (byte) 0xFF && b[1] == (byte) 0xFE) || (b[0] == '<' && b[1] == 0))) {
            return StandardCharsets.UTF_16LE;
        }
        return null;
    }

    /** A character stream must not claim an encoding: drop the declaration's encoding pseudo-attribute. */
    private static String stripDeclaration(String text) {
        String body = text.startsWith("\uFEFF") ? text.substring(1) : text;
        return body.replaceFirst("^(<\\?xml[^?]*?)\\s+encoding\\s*=\\s*(\"[^\"]*\"|'[^']*')", "$1");
    }
}
