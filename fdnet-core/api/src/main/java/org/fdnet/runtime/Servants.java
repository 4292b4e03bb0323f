package org.fdnet.runtime;

import java.util.concurrent.CompletableFuture;
import java.util.function.BooleanSupplier;
import org.fdnet.netinfo.NodeRef;

/**
 * FDNet's Servants (thesis Appendix 2): the network-wide API a Relation gets from
 * {@link org.fdnet.runtime.RelationContext#servants()}. A Relation sees only its own Datas; through
 * these it can find ({@link Visitor}), describe ({@link Reflect}), reshape ({@link Paste}) and follow
 * ({@link NetworkIterator}, {@link LinkageIterator}) the whole network, and load or unload modules.
 * Every change goes through the network's controller as a change request whose events name the calling
 * Relation as their source. On a host of a distributed network they see and reshape every host's nodes through
 * the {@link WholeNetwork} the distribution layer installed (changes are then prepared and committed on every
 * host they touch). (Not CORBA servants: those are the {@code …Impl} classes of {@code corba}.)
 */
public final class Servants {
    private final NodeRef self;
    private final Controller controller;
    private final ServantScope scope;
    private final Reflect reflect;
    private final ServantRegistry registry;
    private final BooleanSupplier selfRuns;

    /**
     * Servants of Relation {@code self} (the engine makes them, {@code engine.EngineServants}): {@code controller}
     * names it as the source of its changes, {@code scope} is what they see (its engine, or the whole network over
     * every host), {@code registry} its engine's servant tree, {@code selfRuns} whether it still runs (its servants go
     * with it).
     */
    public Servants(NodeRef self, Controller controller, ServantScope scope, ServantRegistry registry,
            BooleanSupplier selfRuns) {
        this.selfRuns = selfRuns;
        this.self = self;
        this.controller = controller;
        this.scope = scope;
        this.reflect = new Reflect(scope);
        this.registry = registry;
    }

    /** The Relation these servants work for. */
    public NodeRef self() {
        return self;
    }

    public Visitor visitor() {
        return new Visitor(scope);
    }

    public Reflect reflect() {
        return reflect;
    }

    public Paste paste() {
        return new Paste(scope);
    }

    /** Nodes reachable from {@code start} along the flow of values. */
    public NetworkIterator iterator(NodeRef start) {
        return NetworkIterator.downstream(scope, start);
    }

    /** Nodes whose values can reach {@code start}. */
    public NetworkIterator upstream(NodeRef start) {
        return NetworkIterator.upstream(scope, start);
    }

    /** Connections crossed following the flow of values from {@code start}. */
    public LinkageIterator linkageIterator(NodeRef start) {
        return LinkageIterator.downstream(scope, start);
    }

    public ChangeOutcome load(String module) {
        return scope.load(module);
    }

    public ChangeOutcome unload(String module) {
        return scope.unload(module);
    }

    public ChangeOutcome hold(String module) {
        return scope.hold(module);
    }

    public ChangeOutcome resume(String module) {
        return scope.resume(module);
    }

    // ---- the servant tree and messages between Relations (thesis Appendix 2)

    /** The root of this engine's servant tree. */
    public ServantNode getRootServant() {
        return registry.getRootServant();
    }

    /**
     * The servant at {@code path} in this engine's tree ({@code planner}, {@code arm/planner}), made on demand when
     * its last name is a registered servant class.
     *
     * @throws MessageRefusedException when there is none
     */
    public ServantNode getServant(String path) {
        return registry.getServant(path);
    }

    /**
     * Puts {@code servant} at {@code path} for other Relations (on any host) to message; withdraw it in {@code close}.
     * It also leaves the tree by itself once this Relation no longer runs.
     */
    public ServantNode offer(String path, MessageServant servant) {
        return registry.offer(path, servant, selfRuns);
    }

    public void withdraw(ServantNode offered) {
        registry.withdraw(offered);
    }

    /**
     * Sends {@code message} with {@code argument} to the servant at {@code path} (this host's first, else any host's)
     * and returns at once: {@code listener} hears the reply, or why there is none, on a messaging thread.
     */
    public void sendMessage(String path, String message, Value argument, ReturnListener listener) {
        registry.sendMessage(path, message, argument, listener);
    }

    /** {@link #sendMessage(String, String, Value, ReturnListener)} as a future (refusals complete it exceptionally). */
    public CompletableFuture<Value> sendMessage(String path, String message, Value argument) {
        CompletableFuture<Value> reply = new CompletableFuture<>();
        registry.sendMessage(path, message, argument,
                ReturnListener.of(reply::complete, reason -> reply.completeExceptionally(new MessageRefusedException(reason))));
        return reply;
    }

    /** The registry of servant classes and instances this Relation's engine keeps. */
    public ServantRegistry registry() {
        return registry;
    }

    /** The controller of this Relation's own engine (values, parameters, snapshot of this host's share). */
    public Controller controller() {
        return controller;
    }
}
