package org.fdnet.netinfo.xml;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import org.xml.sax.InputSource;

/**
 * The DTDs FDNet validates against. Files are always checked against these bundled copies, whatever
 * their DOCTYPE says (and when they have none): a file cannot choose a weaker grammar or make the
 * parser fetch anything.
 */
public enum BundledDtd {
    CNET("cnet", "cnet.dtd"),
    FDG("fdg", "fdg.dtd");

    private final String root;
    private final String fileName;
    private volatile byte[] bytes;

    BundledDtd(String root, String fileName) {
        this.root = root;
        this.fileName = fileName;
    }

    /** The root element the DTD declares. */
    public String root() {
        return root;
    }

    /** The DTD's file name, used as the DOCTYPE's SYSTEM id when saving. */
    public String fileName() {
        return fileName;
    }

    InputSource inputSource() {
        InputSource source = new InputSource(new ByteArrayInputStream(bytes()));
        source.setSystemId("fdnet:bundled/" + fileName);
        return source;
    }

    private byte[] bytes() {
        byte[] b = bytes;
        if (b == null) {
            try (InputStream in = BundledDtd.class.getResourceAsStream("dtd/" + fileName)) {
                if (in == null) {
                    throw new IllegalStateException("the bundled DTD dtd/" + fileName + " is missing from the class path");
                }
                b = in.readAllBytes();
            } catch (IOException e) {
                throw new UncheckedIOException("cannot read the bundled DTD " + fileName, e);
            }
            bytes = b;
        }
        return b;
    }
}
