package org.fdnet.netinfo.xml;

import java.util.List;
import java.util.stream.Collectors;

/** A file that could not be loaded, with every problem found in it, in file order. */
public class NetworkFileException extends Exception {
    private static final long serialVersionUID = 1L;

    private final transient List<Problem> problems;

    public NetworkFileException(List<Problem> problems) {
        super(problems.stream().map(Problem::toString).collect(Collectors.joining("\n")));
        this.problems = List.copyOf(problems);
    }

    public List<Problem> problems() {
        return problems;
    }
}
