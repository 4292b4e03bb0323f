package org.fdnet.corba.cli;

import org.fdnet.corba.OrbSettings;
import org.fdnet.tls.TlsOptions;
import picocli.CommandLine.Mixin;
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

    @Mixin
    TlsOptions tls = new TlsOptions(); // plain, on loopback, when made in code (the editor's Run)

    /**
     * Turns TLS on when asked and refuses to listen off loopback without it (see {@link TlsOptions}).
     *
     * @throws IllegalArgumentException when the key store cannot be used
     * @throws IllegalStateException    when {@code --bind} is not loopback and there is neither TLS nor {@code --insecure}
     */
    public void secure(String what) {
        tls.apply();
        tls.requireSafeBind(what, bind);
    }

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
