/**
 * Mutual TLS for every FDNet connection between processes: IIOP (hosts, naming service, control objects) and
 * the logger's receiver and viewer ports.
 *
 * <pre>
 *   fdnet keys --out DIR flyer crawler logger …      (KeyMaker: JDK keytool)
 *        DIR/ca.p12        the network's CA (its private key: keep it off the robots)
 *        DIR/NAME.p12      NAME's key + certificate signed by the CA + the CA as the only trusted entry
 *        DIR/password      the stores' password (owner-only)
 *        DIR/permissions   who may do what (Permissions), and permissions.sig: the CA's signature of it
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
 *
 * <p>Once admitted, a member may do what the network's permissions file grants its certificate's name ({@link
 * org.fdnet.tls.Permissions}, {@link org.fdnet.tls.Right}); {@link org.fdnet.tls.PermissionsFile} checks the CA's
 * signature when the identity loads, and {@link org.fdnet.tls.PeerCertificate} names the member at the other end of a
 * connection for the servers that enforce it (the ORB's servants, the logger's receiver).
 */
package org.fdnet.tls;
