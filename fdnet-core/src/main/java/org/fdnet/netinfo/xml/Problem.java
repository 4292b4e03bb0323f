package org.fdnet.netinfo.xml;

import java.nio.file.Path;

/**
 * One thing wrong with a file, at a place: printed {@code file:line:col: message}, or
 * {@code file: message} when the problem has no place (an unreadable file).
 */
public record Problem(Path file, int line, int column, String message) implements Comparable<Problem> {

    @Override
    public int compareTo(Problem other) {
        int byLine = Integer.compare(line, other.line);
        return byLine != 0 ? byLine : Integer.compare(column, other.column);
    }

    @Override
    public String toString() {
        return line > 0 ? file + ":" + line + ":" + Math.max(column, 1) + ": " + message : file + ": " + message;
    }
}
