package org.fdnet.run;

import java.io.PrintWriter;
import java.util.Map;
import org.fdnet.control.LiveNetwork;
import org.fdnet.control.LocalLiveNetwork;
import org.fdnet.corba.cli.ControlOptions;
import org.fdnet.corba.control.ControlPublication;
import org.fdnet.event.client.CommitReport;
import org.fdnet.event.client.LoggerClient;
import org.fdnet.runtime.NetworkControl;
import org.fdnet.runtime.cli.SimulatedPlant;
import org.fdnet.runtime.engine.RuntimeNetwork;

/** A run on this machine alone: one engine, maybe joined to a simulated plant, recorded by one logger client. */
final class LocalTarget implements RunTarget {
    private final String host;
    private final RuntimeNetwork network;
    private final SimulatedPlant.Run plant;
    private final LoggerClient logger;
    private final ControlOptions control;
    private final String loggerViewer;

    LocalTarget(String host, RuntimeNetwork network, SimulatedPlant.Run plant, LoggerClient logger,
                ControlOptions control, String loggerViewer) {
        this.host = host;
        this.network = network;
        this.plant = plant;
        this.logger = logger;
        this.control = control;
        this.loggerViewer = loggerViewer;
    }

    @Override
    public NetworkControl control() {
        return network.controller();
    }

    @Override
    public RuntimeNetwork engine() {
        return network;
    }

    @Override
    public LiveNetwork live(String name) {
        return new LocalLiveNetwork(name, network.controller(), java.util.Optional.ofNullable(loggerViewer));
    }

    @Override
    public ControlPublication publish(LiveNetwork live, PrintWriter out) {
        return control.publish(live, out);
    }

    @Override
    public String status() {
        return plant == null ? "" : plant.status();
    }

    @Override
    public void summary(PrintWriter out) {
        if (plant != null) {
            out.println(plant.summary());
        }
    }

    @Override
    public Map<String, String> stop() {
        if (plant != null) {
            plant.close();
        }
        network.close();
        if (logger == null) {
            return Map.of();
        }
        logger.close();
        return Map.of(host, CommitReport.of(logger));
    }
}
