package org.fdnet.run;

import java.io.PrintWriter;
import java.util.Map;
import org.fdnet.control.LiveNetwork;
import org.fdnet.corba.DistributedRun;
import org.fdnet.corba.control.ControlPublication;
import org.fdnet.corba.control.DistributedLiveNetwork;
import org.fdnet.runtime.NetworkControl;
import org.fdnet.runtime.engine.RuntimeNetwork;

/** A run over several hosts: a {@link DistributedRun} whose control object is registered in its naming service. */
final class DistributedTarget implements RunTarget {
    private final DistributedRun run;
    private final boolean publishControl;

    DistributedTarget(DistributedRun run, boolean publishControl) {
        this.run = run;
        this.publishControl = publishControl;
    }

    @Override
    public NetworkControl control() {
        return run.control();
    }

    @Override
    public RuntimeNetwork engine() {
        return run.localEngine().runtime();
    }

    @Override
    public LiveNetwork live(String name) {
        return new DistributedLiveNetwork(name, run.control(), run.deployment(), run.loggerViewerAddress());
    }

    /** Registered in the naming service; a run whose naming service refuses still runs, and says so. */
    @Override
    public ControlPublication publish(LiveNetwork live, PrintWriter out) {
        if (!publishControl) {
            return null;
        }
        try {
            ControlPublication p = ControlPublication.inNaming(live, run.orb());
            out.println(p.announcement());
            return p;
        } catch (RuntimeException e) {
            out.println("the control object is not published: " + e.getMessage());
            return null;
        }
    }

    @Override
    public String status() {
        return run.status();
    }

    @Override
    public void summary(PrintWriter out) {
        run.summary(out);
    }

    @Override
    public Map<String, String> stop() {
        return run.stop();
    }
}
