package org.fdnet.netinfo.xml;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.Charset;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

/** Writes test files: a .fdn body wrapped in the usual header, in any encoding. */
final class NetworkFiles {
    static final String DOCTYPE = "<!DOCTYPE cnet SYSTEM \"cnet.dtd\">\n";

    private NetworkFiles() {
    }

    static String node(String element, String name) {
        return "<" + element + "><name>" + name + "</name><host>localhost</host><path></path><class>C</class></" + element + ">\n";
    }

    static String data(String name) {
        return node("dstructure", name);
    }

    static String relation(String name) {
        return node("pstructure", name);
    }

    static String read(String data, String proc) {
        return "<read><data>" + data + "</data><proc>" + proc + "</proc></read>\n";
    }

    static String write(String data, String proc) {
        return "<write><data>" + data + "</data><proc>" + proc + "</proc></write>\n";
    }

    /** A UTF-8 file: declaration, DOCTYPE, then {@code body} (which starts on line 3). */
    static Path utf8(Path dir, String body) {
        return file(dir, "net.fdn", "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n" + DOCTYPE + body, StandardCharsets.UTF_8);
    }

    static Path file(Path dir, String name, String text, Charset charset) {
        return bytes(dir, name, text.getBytes(charset));
    }

    static Path bytes(Path dir, String name, byte[] content) {
        try {
            Path file = dir.resolve(name);
            Files.write(file, content);
            return file;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
