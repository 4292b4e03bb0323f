package org.fdnet.corba.cli;

import org.fdnet.corba.OrbSettings;
import picocli.CommandLine.Option;

/** Where the naming service is: {@code --naming corbaloc} or {@code --naming-port P} on 127.0.0.1. */
public final class NamingOptions {
    @Option(names = "--naming", description = "corbaloc of the naming service, e.g. corbaloc::127.0.0.1:2809/NameService")
    String corbaloc;

    @Option(names = "--naming-port", description = "port of a naming service on 127.0.0.1 (default: 2809)")
    Integer port;

    @Option(names = "--bind", description = "address this process listens on (default: ${DEFAULT-VALUE})",
            defaultValue = OrbSettings.LOOPBACK)
    String bind = OrbSettings.LOOPBACK; // also when made in code, not parsed (the editor's Run)

    public String corbaloc() {
        if (corbaloc != null) {
            return corbaloc;
        }
        return OrbSettings.namingCorbaloc(OrbSettings.LOOPBACK, port == null ? 2809 : port);
    }

    public OrbSettings orbSettings() {
        return OrbSettings.defaults().withBindAddress(bind).withNaming(corbaloc());
    }
}
