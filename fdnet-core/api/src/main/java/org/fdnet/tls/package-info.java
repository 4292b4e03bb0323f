/**
 * Mutual TLS for every FDNet connection between processes: IIOP (hosts, naming service, control objects) and
 * the logger's receiver and viewer ports.
 *
 * <pre>
 *   fdnet keys --out DIR flyer crawler logger …      (KeyMaker: JDK keytool)
 *        DIR/ca.p12        the network's CA (its private key: keep it off the robots)
 *        DIR/NAME.p12      NAME's key + certificate signed by the CA + the CA as the only trusted entry
 *        DIR/password      the stores' password (owner-only)
 *        │
 *   fdnet host|run|naming|logger|viewer … --tls DIR/NAME.p12
 *        │  TlsIdentity.load ── SSLContext (key: NAME; trust: the CA only)
 *        ▼
 *   TransportSecurity (one per process) ──▶ OrbSettings: JacORB SSLIOP through corba.IiopTls*SocketFactory
 *                                        └▶ logger TcpServer / LoggerClient / ViewerClient sockets
 * </pre>
 *
 * Each end verifies the other: servers require a client certificate, clients check the server's, both against
 * the network's CA alone, so a certificate of another network (or none) is refused during the handshake, before
 * a byte of FDNet protocol is read. Off by default: on 127.0.0.1 nothing changes; a process bound to another
 * address refuses to start without {@code --tls} unless told {@code --insecure} ({@link
 * org.fdnet.tls.TransportSecurity#requireSafeBind}).
 */
package org.fdnet.tls;
