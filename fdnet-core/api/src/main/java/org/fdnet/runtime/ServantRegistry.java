package org.fdnet.runtime;

import java.lang.reflect.InvocationTargetException;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.BooleanSupplier;
import java.util.function.Supplier;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The servant system of one engine (thesis Appendix 2, {@code cnet.core.Servant}'s static part, made an object so
 * that several networks can run in one process): the registry of servant classes, their named instances
 * ({@code name:N}), the servant tree from its root, and the delivery of messages.
 *
 * <pre>
 *   Relation A: sendMessage("arm/planner", "plan", v, listener) ─▶ messaging thread
 *        ├─ a servant at that path in this engine's tree ─▶ answer(message, v) ─────────────┐
 *        └─ none here, network over several hosts ─▶ WholeNetwork.message ─▶ coordinator ─▶ │
 *                       the host whose tree has it: answer(message, v) ◀─ two-way CORBA call │
 *   listener.returned(reply) / listener.refused(reason) ◀───────────────────────────────────┘
 * </pre>
 *
 * A message is answered by the first servant found at its path: this engine's own first, then (over several hosts)
 * the first host the coordinator finds one on; so give servants network-wide unique paths. Each message gets exactly
 * one call of its listener.
 */
public final class ServantRegistry implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(ServantRegistry.class);

    private final ServantNode root = new ServantNode("", null, null);
    private final Map<String, Class<? extends MessageServant>> classes = new ConcurrentHashMap<>();
    private final Map<String, ServantNode> instances = new ConcurrentHashMap<>();
    private final Supplier<WholeNetwork> wholeNetwork;
    private final ExecutorService messaging;

    /** @param wholeNetwork the network over every host, or a supplier of {@code null} while there is none */
    public ServantRegistry(Supplier<WholeNetwork> wholeNetwork) {
        this.wholeNetwork = wholeNetwork;
        AtomicInteger threads = new AtomicInteger();
        this.messaging = Executors.newFixedThreadPool(2, r -> {
            Thread t = new Thread(r, "fdnet-servant-messages-" + threads.incrementAndGet());
            t.setDaemon(true);
            return t;
        });
    }

    /**
     * The servant every other descends from.
     *
     * @return the root, path {@code /}; it answers no message
     */
    public ServantNode getRootServant() {
        return root;
    }

    // ---------------------------------------------------------------- classes and instances

    /**
     * Registers a servant class under {@code name}; its instances are made with its public no-argument constructor.
     *
     * @param name the class's name in servant paths, non-empty, without {@code /} or surrounding spaces; a class
     *             registered under it before is replaced
     * @param type the class; it needs a public no-argument constructor
     * @throws MessageRefusedException when {@code name} is malformed
     */
    public void setServantClass(String name, Class<? extends MessageServant> type) {
        checkName(name);
        classes.put(name, type);
    }

    /**
     * The servant class registered under {@code name}.
     *
     * @param name the name it was registered under
     * @return the class, or null when none is registered under that name
     */
    public Class<? extends MessageServant> getServantClass(String name) {
        return classes.get(name);
    }

    /**
     * Whether a servant class is registered under {@code name}.
     *
     * @param name the name to look up
     * @return true when {@link #getServantClass} would find one
     */
    public boolean containsServantClass(String name) {
        return classes.containsKey(name);
    }

    /**
     * A new instance of the servant class {@code className}, below the root under the first free name
     * {@code className:N} (N from 1), as the thesis's {@code createName} names them.
     *
     * @param className the name the servant class was registered under
     * @return the new instance, below the root
     * @throws MessageRefusedException when no class is registered under that name or it cannot be made
     */
    public ServantNode instantiate(String className) {
        MessageServant servant = newInstance(className);
        for (int n = 1; ; n++) {
            ServantNode node = new ServantNode(className + ":" + n, root, servant);
            if (root.adopt(node)) {
                instances.put(node.name(), node);
                return node;
            }
        }
    }

    /**
     * The instance named {@code name:N}, or {@code null}.
     *
     * @param instanceName the name {@link #instantiate} gave it, e.g. {@code planner:2}
     * @return the instance, or null when there is none of that name
     */
    public ServantNode getServantInstance(String instanceName) {
        return instances.get(instanceName);
    }

    /**
     * Removes an instance from the registry and from the tree; nothing happens when there is none of that name.
     *
     * @param instanceName the name {@link #instantiate} gave it, e.g. {@code planner:2}
     */
    public void releaseServantInstance(String instanceName) {
        ServantNode node = instances.remove(instanceName);
        if (node != null) {
            root.release(node);
        }
    }

    private MessageServant newInstance(String className) {
        Class<? extends MessageServant> type = classes.get(className);
        if (type == null) {
            throw new MessageRefusedException("no servant class is registered as '" + className + "'");
        }
        try {
            return type.getConstructor().newInstance();
        } catch (InvocationTargetException e) {
            throw new MessageRefusedException("servant class '" + className + "' (" + type.getName()
                    + ") failed to start: " + e.getCause());
        } catch (ReflectiveOperationException e) {
            throw new MessageRefusedException("servant class '" + className + "' (" + type.getName()
                    + ") has no public no-argument constructor: " + e);
        }
    }

    // ---------------------------------------------------------------- the tree

    /**
     * Puts {@code servant} at {@code path} (its parents are made as grouping servants when missing) until it is
     * {@linkplain #withdraw withdrawn}: a Relation offers a servant in its first firing and withdraws it in
     * {@code close}.
     *
     * @param path    where to put it, e.g. {@code arm/planner} (a leading {@code /} is allowed)
     * @param servant what answers the messages sent to that path
     * @return the servant's place in the tree, to pass to {@link #withdraw}
     * @throws MessageRefusedException when the path is malformed or a servant is already there
     */
    public ServantNode offer(String path, MessageServant servant) {
        return offer(path, servant, () -> true);
    }

    /**
     * {@link #offer(String, MessageServant)} on behalf of a Relation: the servant leaves the tree by itself once
     * {@code ownerRuns} is false (the Relation failed, was unloaded, destroyed or replaced), even when the Relation
     * did not withdraw it; a new instance of the Relation may then offer the same path.
     *
     * @param path      where to put it, e.g. {@code arm/planner} (a leading {@code /} is allowed)
     * @param servant   what answers the messages sent to that path
     * @param ownerRuns true while the offering Relation runs; asked whenever the path is looked up
     * @return the servant's place in the tree, to pass to {@link #withdraw}
     * @throws MessageRefusedException when the path is malformed or taken by a servant whose owner still runs
     */
    public ServantNode offer(String path, MessageServant servant, BooleanSupplier ownerRuns) {
        List<String> names = parts(path);
        ServantNode parent = root;
        for (String name : names.subList(0, names.size() - 1)) {
            parent = parent.childOrAdd(name, null);
        }
        ServantNode node = new ServantNode(names.get(names.size() - 1), parent, servant, ownerRuns);
        if (!parent.adopt(node)) {
            throw new MessageRefusedException("servant path " + node.path() + " is taken");
        }
        return node;
    }

    /**
     * Takes {@code node} out of the tree (with what is below it); later messages to its path are refused.
     *
     * @param node a servant of this registry's tree; the root is left alone
     */
    public void withdraw(ServantNode node) {
        if (node.getParent() != null) {
            node.getParent().release(node);
        }
    }

    /**
     * The servant at {@code path} in this engine's tree ({@code a/b} or {@code /a/b}), or {@code null}. A servant
     * whose offering Relation no longer runs is withdrawn here and not found.
     *
     * @param path the servant's names from the root, separated by {@code /}
     * @return the servant, or null when there is none at that path
     * @throws MessageRefusedException when the path is malformed
     */
    public ServantNode find(String path) {
        ServantNode node = root;
        for (String name : parts(path)) {
            node = node.child(name);
            if (node == null) {
                return null;
            }
        }
        if (!node.ownerRuns()) {
            withdraw(node);
            return null;
        }
        return node;
    }

    /**
     * The servant at {@code path}; when there is none but its last name is a registered servant class and its parent
     * exists, an instance of that class is made there on demand (a parent "instantiates any child servant").
     *
     * @param path the servant's names from the root, separated by {@code /}
     * @return the servant found or made
     * @throws MessageRefusedException when there is no such servant and none can be made
     */
    public ServantNode getServant(String path) {
        ServantNode found = find(path);
        if (found != null) {
            return found;
        }
        List<String> names = parts(path);
        String last = names.get(names.size() - 1);
        ServantNode parent = names.size() == 1 ? root : find(String.join("/", names.subList(0, names.size() - 1)));
        if (parent == null || !classes.containsKey(last)) {
            throw new MessageRefusedException("no servant at /" + String.join("/", names));
        }
        return parent.childOrAdd(last, newInstance(last));
    }

    private static List<String> parts(String path) {
        String trimmed = path == null ? "" : path.strip();
        if (trimmed.startsWith("/")) {
            trimmed = trimmed.substring(1);
        }
        if (trimmed.isEmpty()) {
            throw new MessageRefusedException("a servant path names at least one servant (was '" + path + "')");
        }
        List<String> names = List.of(trimmed.split("/", -1));
        names.forEach(ServantRegistry::checkName);
        return names;
    }

    private static void checkName(String name) {
        if (name.isBlank() || name.indexOf('/') >= 0 || !name.equals(name.strip())) {
            throw new MessageRefusedException("servant name '" + name + "' must be non-empty, without '/' or surrounding spaces");
        }
    }

    // ---------------------------------------------------------------- messages

    /**
     * Sends {@code message} with {@code argument} to the servant at {@code path}, here or on another host, and
     * returns at once; {@code listener} hears the reply or the reason there is none, once.
     *
     * @param path     the servant's path, e.g. {@code arm/planner}
     * @param message  what to do, as the servant understands it
     * @param argument the message's argument, any FDNet value
     * @param listener told exactly once, on a messaging thread: the reply, or the reason there is none
     */
    public void sendMessage(String path, String message, Value argument, ReturnListener listener) {
        Delivery delivery = new Delivery(path, message, argument, listener);
        try {
            messaging.execute(delivery);
        } catch (RejectedExecutionException e) {
            delivery.notSent();
        }
    }

    /** One message on its way; a message still queued when the network stops is refused, never dropped silently. */
    private final class Delivery implements Runnable {
        private final String path;
        private final String message;
        private final Value argument;
        private final ReturnListener listener;

        Delivery(String path, String message, Value argument, ReturnListener listener) {
            this.path = path;
            this.message = message;
            this.argument = argument;
            this.listener = listener;
        }

        @Override
        public void run() {
            deliver(path, message, argument, listener);
        }

        void notSent() {
            tell(listener, null, "the network has stopped: message " + message + " to " + path + " not sent");
        }
    }

    private void deliver(String path, String message, Value argument, ReturnListener listener) {
        Value reply;
        try {
            reply = answer(path, message, argument);
        } catch (MessageRefusedException e) {
            tell(listener, null, e.getMessage());
            return;
        } catch (RuntimeException e) {
            tell(listener, null, "servant " + path + " failed on " + message + ": " + e);
            return;
        }
        tell(listener, reply, null);
    }

    private Value answer(String path, String message, Value argument) {
        if (answersHere(path)) {
            return answerHere(path, message, argument);
        }
        WholeNetwork whole = wholeNetwork.get();
        if (whole == null) {
            throw new MessageRefusedException("no servant at " + path + " in this network");
        }
        return whole.message(path, message, argument);
    }

    /**
     * Whether a servant at {@code path} is here or can be made here on demand.
     *
     * @param path the servant's path
     * @return true when this engine answers messages to it; false too for a malformed path
     */
    public boolean answersHere(String path) {
        try {
            List<String> names = parts(path);
            return find(path) != null || classes.containsKey(names.get(names.size() - 1))
                    && (names.size() == 1 || find(String.join("/", names.subList(0, names.size() - 1))) != null);
        } catch (MessageRefusedException e) {
            return false;
        }
    }

    /**
     * The answer of this engine's servant at {@code path}, on the calling thread (a host answering for another).
     *
     * @param path     the servant's path
     * @param message  what to do, as the servant understands it
     * @param argument the message's argument
     * @return the servant's reply
     * @throws MessageRefusedException when there is no servant here or it refuses the message
     */
    public Value answerHere(String path, String message, Value argument) {
        return getServant(path).answer(message, argument);
    }

    private static void tell(ReturnListener listener, Value reply, String reason) {
        try {
            if (reason == null) {
                listener.returned(reply);
            } else {
                listener.refused(reason);
            }
        } catch (RuntimeException e) {
            LOG.warn("return listener {} failed", listener, e);
        }
    }

    /** Stops delivering: messages still queued and messages sent from now on are refused. */
    @Override
    public void close() {
        for (Runnable queued : messaging.shutdownNow()) {
            ((Delivery) queued).notSent();
        }
    }
}
