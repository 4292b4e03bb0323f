package org.fdnet.netinfo;

/**
 * The rules every network obeys, in one place: the repository applies them to files, NetworkInfo to
 * edits. Each check throws {@link EditRefusedException} with the message a user sees.
 */
public final class ModelRules {
    private ModelRules() {
    }

    /**
     * Module and node names: not blank, no '/', no control characters, no surrounding white space.
     *
     * @param what the kind of name for the message: {@code module} or {@code node}
     * @param name the name to check, may be null
     * @throws EditRefusedException when the name breaks a rule, saying which
     */
    public static void checkName(String what, String name) {
        if (name == null || name.isBlank()) {
            throw new EditRefusedException(what + " name may not be empty");
        }
        if (name.indexOf('/') >= 0) {
            throw new EditRefusedException(what + " name '" + name + "' may not contain '/' (it separates module and node)");
        }
        if (hasControlCharacter(name)) {
            throw new EditRefusedException(what + " name '" + name + "' may not contain control characters (tabs, line breaks)");
        }
        if (!name.equals(name.strip())) {
            throw new EditRefusedException(what + " name '" + name + "' may not begin or end with white space");
        }
    }

    /**
     * A module's path: names separated by '/', each a valid module name ({@code Arm} or {@code Arm/Hand}); no
     * module lies inside {@code main}, whose place is the top of the network.
     *
     * @param path the module's full name, may be null
     * @throws EditRefusedException when the path breaks a rule, saying which
     */
    public static void checkModulePath(String path) {
        if (path == null || path.isBlank()) {
            throw new EditRefusedException("module name may not be empty");
        }
        for (String part : path.split("/", -1)) {
            checkName("module", part);
        }
        if (path.startsWith(ModuleInfo.MAIN + "/")) {
            throw new EditRefusedException("module '" + path + "': no module lies inside 'main' (put it at the top level)");
        }
    }

    private static boolean hasControlCharacter(String name) {
        for (int i = 0; i < name.length(); i++) {
            if (Character.isISOControl(name.charAt(i))) {
                return true;
            }
        }
        return false;
    }

    /**
     * A node has a valid name and names a class.
     *
     * @param node the node's definition
     * @throws EditRefusedException when the name is invalid or the class name blank
     */
    public static void checkNode(NodeInfo node) {
        checkName("node", node.name());
        if (node.className().isBlank()) {
            throw new EditRefusedException("node '" + node.name() + "' names no class");
        }
    }

    /**
     * A connection must join an existing Data (its data end) and an existing Relation (its relation end).
     *
     * @param network the network the connection is to join
     * @param c       the connection
     * @throws EditRefusedException when an end's module or node is missing or of the wrong kind
     */
    public static void checkConnectionEnds(NetworkInfo network, ConnectionInfo c) {
        checkEnd(network, c, c.data(), NodeKind.DATA);
        checkEnd(network, c, c.relation(), NodeKind.RELATION);
    }

    private static void checkEnd(NetworkInfo network, ConnectionInfo c, NodeRef ref, NodeKind expected) {
        ModuleInfo module = network.module(ref.module());
        if (module == null) {
            throw new EditRefusedException(c.kind().label() + " names " + ref + " but there is no module '" + ref.module() + "'");
        }
        NodeInfo node = module.node(ref.node());
        if (node == null) {
            throw new EditRefusedException(c.kind().label() + " names " + ref + " but module '" + ref.module()
                    + "' has no node '" + ref.node() + "'");
        }
        if (node.kind() != expected) {
            throw new EditRefusedException(c.kind().label() + " must join one Data and one Relation, but " + ref
                    + " is a " + node.kind().label() + " where a " + expected.label() + " is expected");
        }
    }
}
