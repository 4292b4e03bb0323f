package org.fdnet.cli;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import org.fdnet.tls.KeyMaker;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code fdnet keys}: a network's CA and one certificate per process, for {@code --tls}. */
@Command(name = "keys", mixinStandardHelpOptions = true,
        description = {"Make a network's CA and a certificate for each named process (JDK keytool), for --tls.",
                "Give each process its own DIR/NAME.p12 and the DIR/password file; keep DIR/ca.p12 off the robots.",
                "Run again with new names to add processes to the same network.",
                "DIR/permissions (signed by the CA in DIR/permissions.sig) says who may do what; its default allows"
                        + " everything to every member. After editing it, sign it again with --sign-permissions."})
public final class KeysCommand implements Callable<Integer> {
    @Option(names = "--out", required = true, paramLabel = "DIR", description = "folder for the network's key files")
    Path dir;

    @Option(names = "--sign-permissions",
            description = "check DIR/permissions and sign it again with the CA's key (after editing it); no NAME needed")
    boolean signPermissions;

    @Parameters(arity = "0..*", paramLabel = "NAME",
            description = "process names: hosts (flyer, crawler), the run's host, naming, logger, viewer, …")
    List<String> names;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() throws InterruptedException {
        KeyMaker maker = new KeyMaker(dir);
        if (names == null || names.isEmpty()) {
            if (!signPermissions) {
                spec.commandLine().getErr().println("fdnet keys: name at least one process (or give --sign-permissions)");
                return 2;
            }
            names = List.of();
        }
        try {
            if (signPermissions) {
                spec.commandLine().getOut().println("signed " + maker.signPermissions());
            }
            for (Path made : maker.make(names)) {
                spec.commandLine().getOut().println("made " + made);
            }
        } catch (IOException | IllegalArgumentException e) {
            spec.commandLine().getErr().println("fdnet keys: " + e.getMessage());
            return 1;
        }
        for (String n : names) {
            spec.commandLine().getOut().println(n + ": --tls " + maker.store(n));
        }
        return 0;
    }
}
