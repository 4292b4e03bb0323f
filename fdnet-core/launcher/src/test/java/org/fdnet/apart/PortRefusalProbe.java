package org.fdnet.apart;

import java.io.IOException;
import java.io.InputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.UUID;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import javax.net.ssl.SSLSocket;
import org.fdnet.corba.OrbRuntime;
import org.fdnet.corba.OrbSettings;
import org.fdnet.event.wire.FrameWriter;
import org.fdnet.event.wire.Hello;
import org.fdnet.tls.TlsIdentity;
import org.omg.CORBA.BAD_OPERATION;
import org.omg.CORBA.OBJECT_NOT_EXIST;
import org.omg.CORBA.SystemException;

/**
 * Knocks on ports three ways, from wherever it runs (the test runs it on a host of the rig): with a certificate of the
 * network (must be let in), without TLS, and with another network's certificate (both must be refused before
 * anything is served). Without TLS it is a real client of the port's protocol: a plain JacORB call on an IIOP port, a
 * core's HELLO on a logger port. Arguments: {@code MEMBER.p12 FOREIGN.p12 LABEL=ADDRESS:PORT/iiop|logger...}; prints
 * one line per port: {@code port LABEL ADDRESS:PORT member=accepted plain=refused foreign=refused}.
 */
public final class PortRefusalProbe {
    private static final int TIMEOUT_MS = 5_000;
    private static final int TLS_ALERT = 21;

    private PortRefusalProbe() {
    }

    public static void main(String[] args) throws InterruptedException, ExecutionException {
        TlsIdentity member = TlsIdentity.load(Path.of(args[0]));
        TlsIdentity foreign = TlsIdentity.load(Path.of(args[1]));
        List<String> ports = List.of(args).subList(2, args.length);
        ExecutorService knockers = Executors.newFixedThreadPool(ports.size());
        try (OrbRuntime plainOrb = OrbRuntime.start(OrbSettings.defaults().withCallTimeoutMillis(TIMEOUT_MS))) {
            // Every port at once: a member's knock is judged accepted only after a whole read timeout.
            List<Future<String>> lines = new ArrayList<>();
            for (String port : ports) {
                lines.add(knockers.submit(() -> knock(port, member, foreign, plainOrb)));
            }
            for (Future<String> line : lines) {
                System.out.println(line.get());
            }
        } finally {
            knockers.shutdownNow();
        }
        System.out.flush();
    }

    private static String knock(String port, TlsIdentity member, TlsIdentity foreign, OrbRuntime plainOrb) {
        String label = port.substring(0, port.indexOf('='));
        String where = port.substring(port.indexOf('=') + 1, port.lastIndexOf('/'));
        boolean iiop = port.endsWith("/iiop");
        String host = where.substring(0, where.lastIndexOf(':'));
        int number = Integer.parseInt(where.substring(where.lastIndexOf(':') + 1));
        String plain = iiop ? plainCorba(plainOrb, where) : plainHello(host, number);
        return "port " + label + " " + where + " member=" + tls(member, host, number) + " plain=" + plain
                + " foreign=" + tls(foreign, host, number);
    }

    /**
     * A plain JacORB call to the port: {@code answered} when any GIOP reply comes back (even "no such object"),
     * {@code refused} when the connection fails.
     */
    private static String plainCorba(OrbRuntime orb, String where) {
        try {
            orb.orb().string_to_object("corbaloc::" + where + "/NameService")._non_existent();
            return "answered";
        } catch (OBJECT_NOT_EXIST | BAD_OPERATION e) {
            return "answered";
        } catch (SystemException e) {
            return "refused";
        }
    }

    /** A core's HELLO without TLS: {@code answered} when anything but a TLS alert or the end comes back. */
    private static String plainHello(String host, int port) {
        try (Socket s = new Socket()) {
            s.connect(new InetSocketAddress(host, port), TIMEOUT_MS);
            s.setSoTimeout(TIMEOUT_MS);
            FrameWriter w = new FrameWriter();
            Hello.core(UUID.randomUUID(), "plain-probe").write(w);
            w.writeTo(s.getOutputStream());
            s.getOutputStream().flush();
            int first = s.getInputStream().read();
            return first == -1 || first == TLS_ALERT ? "refused" : "answered";
        } catch (SocketTimeoutException e) {
            return "silent";
        } catch (IOException e) {
            return "refused";
        }
    }

    /**
     * A TLS client: {@code accepted} when the server keeps the connection after the handshake (it waits for a request),
     * {@code refused} when the handshake fails or the server closes.
     */
    private static String tls(TlsIdentity identity, String host, int port) {
        try (SSLSocket s = (SSLSocket) identity.context().getSocketFactory().createSocket()) {
            s.connect(new InetSocketAddress(host, port), TIMEOUT_MS);
            s.setSoTimeout(TIMEOUT_MS);
            s.startHandshake();
            // TLS 1.3: the server checks the client's certificate after the client has finished; its refusal comes
            // with the first read. One byte is no whole request of any FDNet protocol: a server that accepted waits.
            s.getOutputStream().write(0);
            s.getOutputStream().flush();
            InputStream in = s.getInputStream();
            return in.read() == -1 ? "refused" : "answered";
        } catch (SocketTimeoutException e) {
            return "accepted";
        } catch (IOException e) {
            return "refused";
        }
    }
}
