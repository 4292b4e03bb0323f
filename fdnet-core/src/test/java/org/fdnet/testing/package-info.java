/**
 * Test support shared by the modules through the fdnet-core test-jar: {@link org.fdnet.testing.RealDisplayExtension}
 * gives GUI tests a real X display ($DISPLAY, or an Xvfb it starts; skipped without one unless CI=true).
 */
package org.fdnet.testing;
