package org.fdnet.corba.cli;

import picocli.CommandLine.Command;

@Command(name = "corba", mixinStandardHelpOptions = true, description = "placeholder")
public final class CorbaBenchmark implements Runnable {
    @Override
    public void run() {
    }
}
