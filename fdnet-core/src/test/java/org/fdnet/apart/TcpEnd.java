package org.fdnet.apart;

import java.io.IOException;
import java.net.ConnectException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.SocketTimeoutException;

/**
 * One end of a TCP connection, run on a rig's host by the tests: {@code listen ADDRESS PORT} accepts connections
 * until killed (printing {@code listening} once bound); {@code connect ADDRESS PORT TIMEOUT_MS} prints
 * {@code connected}, {@code timed out} or {@code refused} and exits.
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
                    server.accept().close();
                }
            }
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
