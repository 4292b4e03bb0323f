package org.fdnet.apart;

import java.io.IOException;
import java.io.OutputStream;
import java.net.ConnectException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.SocketTimeoutException;

/**
 * One end of a TCP connection, run on a rig's host by the tests: {@code listen ADDRESS PORT} accepts connections
 * until killed, reading each to its end (printing {@code listening} once bound); {@code connect ADDRESS PORT
 * TIMEOUT_MS} prints {@code connected}, {@code timed out} or {@code refused} and exits; {@code send ADDRESS PORT BYTES}
 * sends that many bytes and prints how many milliseconds it took until the listener had them all.
 */
public final class TcpEnd {
    private TcpEnd() {
    }

    public static void main(String[] args) throws IOException {
        InetSocketAddress where = new InetSocketAddress(InetAddress.getByName(args[1]), Integer.parseInt(args[2]));
        if (args[0].equals("listen")) {
            try (ServerSocket server = new ServerSocket()) {
                server.bind(where);
                System.out.println("listening");
                System.out.flush();
                while (true) {
                    try (Socket s = server.accept()) {
                        s.getInputStream().transferTo(OutputStream.nullOutputStream());
                        s.getOutputStream().write(1); // everything arrived
                    } catch (IOException clientGone) {
                        // a connect-only client closes at once: serve the next one
                    }
                }
            }
        }
        if (args[0].equals("send")) {
            try (Socket s = new Socket()) {
                s.connect(where, 10_000);
                long start = System.nanoTime();
                s.getOutputStream().write(new byte[Integer.parseInt(args[3])]);
                s.shutdownOutput();
                s.getInputStream().read();
                System.out.println((System.nanoTime() - start) / 1_000_000);
            }
            return;
        }
        try (Socket s = new Socket()) {
            s.connect(where, Integer.parseInt(args[3]));
            System.out.println("connected");
        } catch (SocketTimeoutException e) {
            System.out.println("timed out");
        } catch (ConnectException e) {
            System.out.println("refused: " + e.getMessage());
        }
    }
}
