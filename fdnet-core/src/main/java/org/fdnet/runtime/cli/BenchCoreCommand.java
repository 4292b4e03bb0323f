package org.fdnet.runtime.cli;

import java.util.concurrent.Callable;
import picocli.CommandLine.Command;

/** Placeholder replaced below. */
@Command(name = "core", mixinStandardHelpOptions = true, description = "In-process runtime benchmark.")
public final class BenchCoreCommand implements Callable<Integer> {
    @Override
    public Integer call() {
        return 0;
    }
}
