/**
 * The viewer's command, {@code fdnet viewer} ({@link org.fdnet.viewer.cli.ViewerCommand}: a logger's address and
 * the nodes to plot, then a {@code ViewerWindow}), registered by {@link org.fdnet.viewer.cli.ViewerCommandProvider}.
 * {@code fdnet bench viewer} ({@code BenchViewerCommand}, same package) is in fdnet-viewer/bench, over an
 * {@code InProcessLogger}: the viewer's jar carries no benchmark.
 */
package org.fdnet.viewer.cli;
