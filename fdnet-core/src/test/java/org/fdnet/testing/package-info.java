/**
 * Test support shared by the modules through the fdnet-api test-jar ({@code RealDisplayExtension}, {@code RealDisplay},
 * {@code XvfbInstaller}: no engine needed) and the fdnet-core test-jar ({@link org.fdnet.testing.CliRun}, the whole
 * {@code fdnet} command in-process; {@link org.fdnet.testing.HeardFromNetwork}; {@link org.fdnet.testing.NodeJars}, node classes compiled and jarred in a
 * test). {@code RealDisplayExtension}
 * gives GUI tests a real X display ($DISPLAY, or an Xvfb it starts — installed first as root, like MuJoCo; without
 * one a GUI test fails with the line that installs Xvfb, it is never skipped).
 */
package org.fdnet.testing;
