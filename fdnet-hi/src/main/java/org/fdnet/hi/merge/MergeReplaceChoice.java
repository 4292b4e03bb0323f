package org.fdnet.hi.merge;

import java.util.Objects;

import org.fdnet.hi.edit.NetworkEditor;
import org.fdnet.hi.edit.NetworkEditor.EditResult;
import org.fdnet.netinfo.MergePolicy;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;

/**
 * The logic of the Merge/Replace dialog (thesis Chapter 5 §VII, Figures 28–29): node {@code incoming} is to
 * take the name {@code takenName}, which another node of its module already has. The user chooses:
 * <ul>
 *   <li>Replace — the existing node and all its connections go; {@code incoming} takes its name and keeps only
 *       its own connections ({@link NetworkEditor#replaceNode});</li>
 *   <li>Merge — one node remains under the taken name, with the existing node's host, path and class, every
 *       connection of both, and the parameters the policy says: the existing node's, the incoming node's, or
 *       both ({@link NetworkEditor#mergeNodes} with the existing node first).</li>
 * </ul>
 * Each is one edit (one undo step) through the editor.
 */
public final class MergeReplaceChoice {
    /** What to do with the two nodes. */
    public enum Action { REPLACE, MERGE }

    private final NetworkEditor editor;
    private final NodeRef incoming;
    private final NodeRef existing;

    /**
     * @param incoming  the new or renamed node, already in the network under its own (temporary or old) name
     * @param takenName the name it is to take, which a node of the same module has
     */
    public MergeReplaceChoice(NetworkEditor editor, NodeRef incoming, String takenName) {
        this.editor = Objects.requireNonNull(editor, "editor");
        this.incoming = Objects.requireNonNull(incoming, "incoming");
        this.existing = new NodeRef(incoming.module(), Objects.requireNonNull(takenName, "takenName"));
    }

    public NodeRef incoming() {
        return incoming;
    }

    public NodeRef existing() {
        return existing;
    }

    /** Why neither action can run (a node is gone, or they are one node), or null. */
    public String whyNot() {
        if (editor.network().node(incoming) == null) {
            return "node " + incoming + " no longer exists";
        }
        if (editor.network().node(existing) == null) {
            return "no node is named " + existing + " any more: rename " + incoming + " directly";
        }
        if (incoming.equals(existing)) {
            return incoming + " already has that name";
        }
        return null;
    }

    /** Why Merge cannot run (a Data cannot merge with a Relation), or null. */
    public String whyNotMerge() {
        String why = whyNot();
        if (why != null) {
            return why;
        }
        NodeInfo a = editor.network().node(existing);
        NodeInfo b = editor.network().node(incoming);
        if (a.kind() != b.kind()) {
            return existing + " is a " + a.kind().label() + " and " + incoming + " a " + b.kind().label()
                    + ": only two nodes of one kind can merge (replace still works)";
        }
        return null;
    }

    /** What the user reads next to each parameter policy. */
    public String describe(MergePolicy policy) {
        switch (policy) {
            case FIRST:
                return "parameters of " + existing + " (the node that has the name)";
            case SECOND:
                return "parameters of " + incoming + " (the node taking the name)";
            case BOTH:
                return "both: those of " + existing + ", then those of " + incoming + " it lacks";
            default:
                throw new AssertionError(policy);
        }
    }

    /** Applies the choice through the editor; {@code policy} matters for Merge only. */
    public EditResult apply(Action action, MergePolicy policy) {
        String why = action == Action.MERGE ? whyNotMerge() : whyNot();
        if (why != null) {
            return EditResult.refused(why);
        }
        if (action == Action.REPLACE) {
            return editor.replaceNode(existing, incoming);
        }
        return editor.mergeNodes(existing, incoming, Objects.requireNonNull(policy, "policy"));
    }
}
