package org.fdnet.hi.live;

import java.util.HashMap;
import java.util.Map;
import javax.swing.SwingUtilities;
import org.fdnet.hi.graph.GraphScene;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.Value;

/**
 * Carries sampled values from the network's thread to the canvas. Texts are made on the network's thread;
 * samples arriving while one hand-over is still queued join it, so the Swing thread never has more than one
 * waiting and the canvas repaints at most as often as samples come (ten a second).
 */
final class LiveValuesRelay {
    private final GraphScene scene;
    private Map<NodeRef, String> waiting;
    private boolean stopped;

    LiveValuesRelay(GraphScene scene) {
        this.scene = scene;
    }

    void offer(Map<NodeRef, Value> latest) {
        Map<NodeRef, String> texts = LiveValueText.of(latest);
        synchronized (this) {
            if (stopped) {
                return;
            }
            if (waiting != null) {
                waiting.putAll(texts);
                return;
            }
            waiting = new HashMap<>(texts);
        }
        SwingUtilities.invokeLater(this::handOver);
    }

    /** No value is shown after this (the session ended). */
    synchronized void stop() {
        stopped = true;
    }

    private void handOver() {
        Map<NodeRef, String> texts;
        synchronized (this) {
            texts = waiting;
            waiting = null;
            if (stopped) {
                return;
            }
        }
        scene.showLiveValues(texts);
    }
}
