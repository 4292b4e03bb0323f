package org.fdnet.corba.cli;

import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import org.fdnet.corba.NamingService;
import org.fdnet.corba.OrbSettings;
import org.fdnet.tls.TlsOptions;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** {@code fdnet naming}: runs the naming service hosts register in, until the process is stopped. */
@Command(name = "naming", mixinStandardHelpOptions = true,
        description = "Run the CORBA naming service (JacORB) that FDNet hosts register in.")
public final class NamingCommand implements Callable<Integer> {
    @Option(names = "--port", description = "port to listen on (default: ${DEFAULT-VALUE})", defaultValue = "2809")
    int port;

    @Option(names = "--bind", description = "address to listen on (default: ${DEFAULT-VALUE})",
            defaultValue = OrbSettings.LOOPBACK)
    String bind;

    @Mixin
    TlsOptions tls;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() {
        String corbaloc;
        try {
            tls.apply();
            tls.requireSafeBind("the naming service", bind);
            corbaloc = NamingService.start(OrbSettings.defaults().withBindAddress(bind).withPort(port), 15_000);
        } catch (IllegalArgumentException | IllegalStateException e) {
            spec.commandLine().getErr().println("fdnet naming: " + e.getMessage());
            return 1;
        }
        System.out.println("fdnet naming ready: " + corbaloc);
        System.out.println("hosts join with: fdnet host --name NAME --naming " + corbaloc);
        System.out.flush();
        awaitStop();
        return 0;
    }

    static void awaitStop() {
        CountDownLatch forever = new CountDownLatch(1);
        try {
            forever.await();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
