package org.fdnet.roq.view;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.concurrent.atomic.AtomicReference;
import javax.swing.JLabel;
import javax.swing.SwingUtilities;
import org.fdnet.roq.sim.Course;
import org.fdnet.roq.sim.Heightfield;
import org.junit.jupiter.api.Test;

/** The demo window's header shows a Japanese network name in a font that has its characters, without a warning. */
class DemoTitleNamesTest {
    @Test
    void shouldShowAJapaneseNetworkNameLegibly() throws Exception {
        String title = "FDNet demo: 歩行ロボット on flat";
        AtomicReference<JLabel> shown = new AtomicReference<>();
        SwingUtilities.invokeAndWait(() -> {
            RoqDemoPanel panel = new RoqDemoPanel(Heightfield.of(Course.flat()));
            panel.title(title);
            shown.set(panel.titleLabel());
        });
        assertThat(shown.get().getText()).isEqualTo(title);
        assertThat(shown.get().getFont().canDisplayUpTo(title)).isEqualTo(-1);
    }
}
