/**
 * Test support shared by the modules through the fdnet-core test-jar: {@link org.fdnet.testing.RealDisplayExtension}
 * gives GUI tests a real X display ($DISPLAY, or an Xvfb it starts — installed first as root, like MuJoCo; without
 * one a GUI test fails with the line that installs Xvfb, it is never skipped).
 */
package org.fdnet.testing;
