package org.fdnet.hi.live;

import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Supplier;
import javax.swing.SwingUtilities;
import org.fdnet.control.LiveNetwork;
import org.fdnet.control.LiveNetworkListener;
import org.fdnet.control.NetworkDiff;
import org.fdnet.hi.edit.EditGate;
import org.fdnet.hi.edit.UndoableNetworkEditor;
import org.fdnet.hi.graph.GraphScene;
import org.fdnet.netinfo.EditRefusedException;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.ChangeOutcome;
import org.fdnet.runtime.Value;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * One attachment of the editor to a running network. While live, the editor's {@link EditGate} sends every
 * edit, undo and redo to the network and the view changes only once it was executed. While collecting, edits
 * stay in the editor as pending changes against {@link #base()}, until {@link #deploy()} applies them all at
 * once (or none). Either way, changes the network makes by itself are followed: after each settled change the
 * snapshot is read (off the Swing thread) and the difference adopted into the editor, which keeps the places of
 * existing nodes and gives new ones a place.
 *
 * <p>Every call to the network (an edit, a module command, a value sent, a deploy) runs on the session's
 * {@link NetworkCallThread}: the status bar says "Sending to NAME: …" and the Swing thread keeps dispatching events
 * until the outcome is there; one change at a time (another one meanwhile is refused at once, saying so). While a
 * change is under way the network's own changes are not adopted; they are read again once it is answered.
 *
 * <p>Swing thread for every public method. Snapshots read before the editor's own executed edit are dropped
 * (they would take it back for a moment) and read again: {@link #epoch} counts executed edits.
 */
public final class LiveSession implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(LiveSession.class);
    private static final int SHOWN_ENTRIES = 3;

    private final LiveNetwork network;
    private final UndoableNetworkEditor editor;
    private final GraphScene scene;
    private final LiveSessionListener view;
    private final ExecutorService reader;
    private final AtomicBoolean readPending = new AtomicBoolean();
    private final AtomicLong epoch = new AtomicLong();
    private final LiveValuesRelay values;
    private final AutoCloseable subscription;
    private final NetworkCallThread calls;
    private NetworkInfo base;
    private boolean collecting;
    private boolean ended;

    private LiveSession(LiveNetwork network, UndoableNetworkEditor editor, GraphScene scene, LiveSessionListener view,
                        NetworkInfo snapshot, boolean collecting) {
        this.network = network;
        this.editor = editor;
        this.scene = scene;
        this.view = view;
        this.base = snapshot;
        this.collecting = collecting;
        this.reader = Executors.newSingleThreadExecutor(r -> {
            Thread t = new Thread(r, "fdnet-hi-live-" + network.name());
            t.setDaemon(true);
            return t;
        });
        this.values = new LiveValuesRelay(scene);
        this.calls = new NetworkCallThread(network.name());
        editor.setGate(collecting ? null : this::sendEdit);
        this.subscription = network.subscribe(new Listener());
    }

    /**
     * Attaches {@code editor} to {@code network}. With {@code collecting} false the editor first becomes the
     * running network (the difference to its snapshot is adopted, keeping the layout); with it true the editor
     * keeps what it has, and that difference is the pending change to deploy.
     */
    public static LiveSession attach(LiveNetwork network, UndoableNetworkEditor editor, GraphScene scene,
                                     LiveSessionListener view, boolean collecting) {
        NetworkInfo snapshot = network.snapshot();
        if (!collecting) {
            NetworkDiff toRunning = NetworkDiff.between(editor.network(), snapshot);
            if (!toRunning.isEmpty()) {
                editor.adopt(toRunning.asEdit());
            }
            if (!Objects.equals(editor.network().name(), snapshot.name())) {
                editor.adopt(n -> n.setName(snapshot.name())); // the difference leaves names out
            }
        }
        LiveSession session = new LiveSession(network, editor, scene, view, snapshot, collecting);
        session.readSoon();
        return session;
    }

    public String name() {
        return network.name();
    }

    /**
     * Where viewers reach the logger recording the running network ({@code HOST:PORT}), when the run knows it. Any
     * thread except the Swing thread: it asks the network (a remote call for a network in another process).
     */
    public Optional<String> loggerViewerAddress() {
        return network.loggerViewerAddress();
    }

    public boolean collecting() {
        return collecting;
    }

    /** The running network as last followed; pending changes are the difference from it to the editor's network. */
    public NetworkInfo base() {
        return base.copy();
    }

    // ---------------------------------------------------------------- edits: live or collected

    /** From now on edits stay here as pending changes; {@link #deploy()} sends them. */
    public void startCollecting() {
        collecting = true;
        editor.setGate(null);
    }

    /** What {@link #deploy()} would apply: the difference from {@link #base()} to the editor's network. */
    public NetworkDiff pending() {
        return NetworkDiff.between(base, editor.network());
    }

    /**
     * Applies every pending change to the running network as one change request. Executed: the session is live
     * again. Refused: nothing changed there, the changes stay pending here.
     */
    public ChangeOutcome deploy() {
        NetworkDiff diff = pending();
        String label = "Deploy " + diff.entries().size() + " changes";
        NetworkInfo from = base.copy();
        NetworkInfo to = editor.network().copy();
        ChangeOutcome outcome = send(label, () -> network.apply(label, from, to));
        if (outcome.executed()) {
            collecting = false;
            base = editor.network().copy();
            editor.setGate(this::sendEdit);
            epoch.incrementAndGet();
            readSoon();
        }
        return outcome;
    }

    /** Forgets the pending changes: the editor shows the running network as it is now, and the session is live. */
    public void discardPending() {
        collecting = false;
        editor.setGate(this::sendEdit);
        followNow();
    }

    private ChangeOutcome sendEdit(String label, NetworkInfo before, NetworkInfo after) {
        ChangeOutcome outcome = send(label, () -> network.apply(label, before, after));
        if (outcome.executed()) {
            base = after;
            epoch.incrementAndGet();
            readSoon();
            view.info("Executed by " + network.name() + ": " + label);
        }
        return outcome;
    }

    // ---------------------------------------------------------------- commands

    public ChangeOutcome load(String module) {
        return command("load module " + module, () -> network.load(module));
    }

    public ChangeOutcome unload(String module) {
        return command("unload module " + module, () -> network.unload(module));
    }

    public ChangeOutcome hold(String module) {
        return command("hold module " + module, () -> network.hold(module));
    }

    public ChangeOutcome resume(String module) {
        return command("resume module " + module, () -> network.resume(module));
    }

    /** Writes {@code text} into the running Data {@code data} (the information panel's "send a value"). */
    public ChangeOutcome send(NodeRef data, String text) {
        return command("send " + data + "=" + text, () -> network.send(data, text));
    }

    /**
     * Sends one change on the session's network thread, the status bar saying so meanwhile; refused at once when
     * another change is still under way. The network's own changes are read again afterwards.
     */
    private ChangeOutcome send(String what, Supplier<ChangeOutcome> change) {
        if (calls.busy()) {
            return ChangeOutcome.failed(what, "still sending the previous change to " + network.name()
                    + "; try again once it is answered");
        }
        view.info("Sending to " + network.name() + ": " + what + " …");
        ChangeOutcome outcome = calls.call(change);
        readSoon();
        return outcome;
    }

    private ChangeOutcome command(String what, Supplier<ChangeOutcome> change) {
        ChangeOutcome outcome = send(what, change);
        if (outcome.executed()) {
            view.info(outcome.toString());
        } else {
            view.error(outcome.toString());
        }
        readSoon();
        return outcome;
    }

    /**
     * Reads the snapshot now (on the session's network thread, this thread waiting for it) and follows it (before
     * saving the running network). False when the
     * network could not be read: the session has then ended as lost.
     */
    public boolean followNow() {
        if (calls.busy()) {
            view.error("Still sending a change to " + network.name() + "; try again once it is answered");
            return false;
        }
        epoch.incrementAndGet();
        try {
            view.info("Reading " + network.name() + " …");
            RunningState state = calls.call(() -> new RunningState(network.snapshot(), network.loadedModules(),
                    network.heldModules()));
            follow(epoch.get(), state.snapshot(), state.loaded(), state.held());
            return true;
        } catch (RuntimeException e) {
            LOG.warn("reading the state of {} failed", network.name(), e);
            lost("cannot read its state: " + e.getMessage());
            return false;
        }
    }

    // ---------------------------------------------------------------- following the network

    /** Reads snapshot and module states on the session's thread; a request while one is queued is the same one. */
    private void readSoon() {
        if (ended || !readPending.compareAndSet(false, true)) {
            return;
        }
        reader.execute(() -> {
            readPending.set(false);
            long seen = epoch.get();
            try {
                NetworkInfo snapshot = network.snapshot();
                Set<String> loaded = network.loadedModules();
                Set<String> held = network.heldModules();
                SwingUtilities.invokeLater(() -> follow(seen, snapshot, loaded, held));
            } catch (RuntimeException e) {
                LOG.warn("reading the state of {} failed", network.name(), e);
                SwingUtilities.invokeLater(() -> lost("cannot read its state: " + e.getMessage()));
            }
        });
    }

    private void follow(long seen, NetworkInfo snapshot, Set<String> loaded, Set<String> held) {
        if (ended || calls.busy()) {
            return; // a change of ours is under way: the state is read again once it is answered
        }
        view.modulesChanged(loaded, held);
        scene.keepLiveValuesOf(loaded);
        if (seen != epoch.get()) {
            readSoon(); // read before our own edit was executed: it would take that edit back for a moment
            return;
        }
        NetworkDiff change = collecting ? NetworkDiff.between(base, snapshot) : NetworkDiff.between(editor.network(), snapshot);
        if (change.isEmpty()) {
            base = snapshot;
            return;
        }
        try {
            editor.adopt(change.asEdit());
            base = snapshot;
            view.info(network.name() + " changed: " + shown(change.entries()));
        } catch (EditRefusedException e) {
            view.error(network.name() + " changed in a way that conflicts with the pending changes (" + e.getMessage()
                    + "); Deploy will say whether they still fit");
        }
    }

    private static String shown(List<NetworkDiff.Entry> entries) {
        StringBuilder sb = new StringBuilder();
        for (int i = 0; i < Math.min(SHOWN_ENTRIES, entries.size()); i++) {
            sb.append(i == 0 ? "" : ", ").append(entries.get(i).text());
        }
        return entries.size() > SHOWN_ENTRIES ? sb + " and " + (entries.size() - SHOWN_ENTRIES) + " more" : sb.toString();
    }

    // ---------------------------------------------------------------- ending

    /** Lets go of the network (it keeps running); the editor stays open offline with what it shows. */
    @Override
    public void close() {
        end(false, "detached from " + network.name());
    }

    private void lost(String reason) {
        end(true, "lost " + network.name() + ": " + reason);
    }

    private void end(boolean lost, String reason) {
        if (ended) {
            return;
        }
        ended = true;
        if (editor.gate() != null) {
            editor.setGate(null);
        }
        reader.shutdownNow();
        calls.close();
        values.stop();
        try {
            subscription.close();
        } catch (Exception e) {
            LOG.debug("closing the subscription to {} failed", network.name(), e);
        }
        if (!lost) {
            network.close();
        }
        scene.clearLiveValues();
        view.ended(lost, reason);
    }

    public boolean ended() {
        return ended;
    }

    /** The running network as read at one moment: its definition and its modules' states. */
    private record RunningState(NetworkInfo snapshot, Set<String> loaded, Set<String> held) {
    }

    private final class Listener implements LiveNetworkListener {
        @Override
        public void changeSettled(ChangeOutcome outcome) {
            readSoon();
        }

        @Override
        public void valuesSampled(Map<NodeRef, Value> latest) {
            values.offer(latest);
        }

        @Override
        public void disconnected(String reason) {
            SwingUtilities.invokeLater(() -> lost(reason));
        }
    }
}
