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
     *
     * @param self       the Relation the servants act for
     * @param controller the controller that names {@code self} as the source of its changes
     * @param scope      what the servants see and change
     * @param registry   the engine's servant tree and message delivery
     * @param selfRuns   true while {@code self} still runs; servants it offered leave the tree once it is false
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

    /**
     * The Relation these servants work for.
     *
     * @return its module and node name
     */
    public NodeRef self() {
        return self;
    }

    /**
     * A Visitor: finds running nodes by class, name or any test, and lists every node the definition holds.
     *
     * @return a new Visitor over this scope
     */
    public Visitor visitor() {
        return new Visitor(scope);
    }

    /**
     * The Reflect servant: describes one node (definition, running state, value, connections).
     *
     * @return the Reflect of this scope
     */
    public Reflect reflect() {
        return reflect;
    }

    /**
     * A Paste: creates and destroys nodes, connects and disconnects them, each as a change request.
     *
     * @return a new Paste over this scope
     */
    public Paste paste() {
        return new Paste(scope);
    }

    /**
     * Nodes reachable from {@code start} along the flow of values.
     *
     * @param start the node to start from (Data or Relation)
     * @return an iterator over the nodes downstream of {@code start}, breadth first
     */
    public NetworkIterator iterator(NodeRef start) {
        return NetworkIterator.downstream(scope, start);
    }

    /**
     * Nodes whose values can reach {@code start}.
     *
     * @param start the node to start from (Data or Relation)
     * @return an iterator over the nodes upstream of {@code start}, breadth first
     */
    public NetworkIterator upstream(NodeRef start) {
        return NetworkIterator.upstream(scope, start);
    }

    /**
     * Connections crossed following the flow of values from {@code start}.
     *
     * @param start the node to start from (Data or Relation)
     * @return an iterator over the connections downstream of {@code start}
     */
    public LinkageIterator linkageIterator(NodeRef start) {
        return LinkageIterator.downstream(scope, start);
    }

    /**
     * Loads a module that is not running, as a change request named after this Relation.
     *
     * @param module the module's name
     * @return executed, or failed with the reason (nothing changed then)
     */
    public ChangeOutcome load(String module) {
        return scope.load(module);
    }

    /**
     * Unloads a running module, as a change request named after this Relation.
     *
     * @param module the module's name
     * @return executed, or failed with the reason (nothing changed then)
     */
    public ChangeOutcome unload(String module) {
        return scope.unload(module);
    }

    /**
     * Pauses a loaded module's Relations, as a change request named after this Relation.
     *
     * @param module the module's name
     * @return executed, or failed with the reason (nothing changed then)
     */
    public ChangeOutcome hold(String module) {
        return scope.hold(module);
    }

    /**
     * Lets a held module's Relations fire again, as a change request named after this Relation.
     *
     * @param module the module's name
     * @return executed, or failed with the reason (nothing changed then)
     */
    public ChangeOutcome resume(String module) {
        return scope.resume(module);
    }

    // ---- the servant tree and messages between Relations (thesis Appendix 2)

    /**
     * The root of this engine's servant tree.
     *
     * @return the root, path {@code /}; it answers no message
     */
    public ServantNode getRootServant() {
        return registry.getRootServant();
    }

    /**
     * The servant at {@code path} in this engine's tree ({@code planner}, {@code arm/planner}), made on demand when
     * its last name is a registered servant class.
     *
     * @param path the servant's names from the root, separated by {@code /} (a leading {@code /} is allowed)
     * @return the servant found or made
     * @throws MessageRefusedException when there is none
     */
    public ServantNode getServant(String path) {
        return registry.getServant(path);
    }

    /**
     * Puts {@code servant} at {@code path} for other Relations (on any host) to message; withdraw it in {@code close}.
     * It also leaves the tree by itself once this Relation no longer runs.
     *
     * @param path    where to put it, e.g. {@code arm/planner}; missing parents are made as grouping servants
     * @param servant what answers the messages sent to that path
     * @return the servant's place in the tree, to pass to {@link #withdraw}
     * @throws MessageRefusedException when the path is malformed or taken by a servant whose Relation still runs
     */
    public ServantNode offer(String path, MessageServant servant) {
        return registry.offer(path, servant, selfRuns);
    }

    /**
     * Takes an offered servant out of the tree; later messages to its path are refused.
     *
     * @param offered what {@link #offer} returned
     */
    public void withdraw(ServantNode offered) {
        registry.withdraw(offered);
    }

    /**
     * Sends {@code message} with {@code argument} to the servant at {@code path} (this host's first, else any host's)
     * and returns at once: {@code listener} hears the reply, or why there is none, on a messaging thread.
     *
     * @param path     the servant's path, e.g. {@code arm/planner}
     * @param message  what to do, as the servant understands it, e.g. {@code plan}
     * @param argument the message's argument, any FDNet value
     * @param listener told exactly once: the reply, or the reason there is none
     */
    public void sendMessage(String path, String message, Value argument, ReturnListener listener) {
        registry.sendMessage(path, message, argument, listener);
    }

    /**
     * {@link #sendMessage(String, String, Value, ReturnListener)} as a future (refusals complete it exceptionally).
     * Do not wait for it inside {@code compute}: the firing would block.
     *
     * @param path     the servant's path, e.g. {@code arm/planner}
     * @param message  what to do, as the servant understands it
     * @param argument the message's argument
     * @return completed with the reply, or exceptionally with a {@link MessageRefusedException} giving the reason
     */
    public CompletableFuture<Value> sendMessage(String path, String message, Value argument) {
        CompletableFuture<Value> reply = new CompletableFuture<>();
        registry.sendMessage(path, message, argument,
                ReturnListener.of(reply::complete, reason -> reply.completeExceptionally(new MessageRefusedException(reason))));
        return reply;
    }

    /**
     * The registry of servant classes and instances this Relation's engine keeps.
     *
     * @return the engine's registry, shared by every Relation of the engine
     */
    public ServantRegistry registry() {
        return registry;
    }

    /**
     * The controller of this Relation's own engine (values, parameters, snapshot of this host's share).
     *
     * @return a controller whose changes name this Relation as their source
     */
    public Controller controller() {
        return controller;
    }
}
