package org.fdnet.corba.cli;

import java.util.concurrent.CountDownLatch;
import org.fdnet.corba.NamingService;
import org.fdnet.corba.OrbSettings;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code fdnet naming}: runs the naming service hosts register in, until the process is stopped. */
@Command(name = "naming", mixinStandardHelpOptions = true,
        description = "Run the CORBA naming service (JacORB) that FDNet hosts register in.")
public final class NamingCommand implements Runnable {
    @Option(names = "--port", description = "port to listen on (default: ${DEFAULT-VALUE})", defaultValue = "2809")
    int port;

    @Option(names = "--bind", description = "address to listen on (default: ${DEFAULT-VALUE})",
            defaultValue = OrbSettings.LOOPBACK)
    String bind;

    @Override
    public void run() {
        OrbSettings settings = OrbSettings.defaults().withBindAddress(bind).withPort(port);
        String corbaloc = NamingService.start(settings, 15_000);
        System.out.println("fdnet naming ready: " + corbaloc);
        System.out.println("hosts join with: fdnet host --name NAME --naming " + corbaloc);
        System.out.flush();
        awaitStop();
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
