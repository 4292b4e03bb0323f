package org.fdnet.runtime.engine;

import java.util.List;

/** A network could not start: every problem found (unknown classes, bad parameters), one per line. */
public class RuntimeStartException extends Exception {
    private static final long serialVersionUID = 1L;
    private final transient List<String> problems;

    public RuntimeStartException(List<String> problems) {
        super(String.join("\n", problems));
        this.problems = List.copyOf(problems);
    }

    public List<String> problems() {
        return problems;
    }
}
