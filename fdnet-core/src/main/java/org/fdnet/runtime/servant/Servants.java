package org.fdnet.runtime.servant;

import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.ChangeOutcome;
import org.fdnet.runtime.Controller;
import org.fdnet.runtime.RuntimeNetwork;

/**
 * FDNet's Servants (thesis Appendix 2): the network-wide API a Relation gets from
 * {@link org.fdnet.runtime.RelationContext#servants()}. A Relation sees only its own Datas; through
 * these it can find ({@link Visitor}), describe ({@link Reflect}), reshape ({@link Paste}) and follow
 * ({@link NetworkIterator}, {@link LinkageIterator}) the whole network, and load or unload modules.
 * Every change goes through the network's controller as a change request whose events name the calling
 * Relation as their source. (Not CORBA servants: those are the {@code …Impl} classes of {@code corba}.)
 */
public final class Servants {
    private final RuntimeNetwork network;
    private final NodeRef self;
    private final Controller controller;
    private final Reflect reflect;

    public Servants(RuntimeNetwork network, NodeRef self, int selfId) {
        this.network = network;
        this.self = self;
        this.controller = network.controllerFor(selfId);
        this.reflect = new Reflect(network, controller);
    }

    /** The Relation these servants work for. */
    public NodeRef self() {
        return self;
    }

    public Visitor visitor() {
        return new Visitor(network, reflect);
    }

    public Reflect reflect() {
        return reflect;
    }

    public Paste paste() {
        return new Paste(controller);
    }

    /** Nodes reachable from {@code start} along the flow of values. */
    public NetworkIterator iterator(NodeRef start) {
        return NetworkIterator.downstream(network, start);
    }

    /** Nodes whose values can reach {@code start}. */
    public NetworkIterator upstream(NodeRef start) {
        return NetworkIterator.upstream(network, start);
    }

    /** Connections crossed following the flow of values from {@code start}. */
    public LinkageIterator linkageIterator(NodeRef start) {
        return LinkageIterator.downstream(network, controller, start);
    }

    public ChangeOutcome load(String module) {
        return controller.load(module);
    }

    public ChangeOutcome unload(String module) {
        return controller.unload(module);
    }

    public ChangeOutcome hold(String module) {
        return controller.hold(module);
    }

    public ChangeOutcome resume(String module) {
        return controller.resume(module);
    }

    /** The controller acting for this Relation (values, parameters, snapshot). */
    public Controller controller() {
        return controller;
    }
}
