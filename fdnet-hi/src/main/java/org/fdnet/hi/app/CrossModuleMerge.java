package org.fdnet.hi.app;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import javax.swing.JOptionPane;
import org.fdnet.netinfo.EditRefusedException;
import org.fdnet.netinfo.MergePolicy;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeRef;

/**
 * The answer for two nodes of different modules, which the thesis's dialog (one module, a name taken)
 * does not cover: NetworkInfo merges across modules, so the graph offers it. Only what can succeed is
 * offered: each action is tried on a copy of the network, so NetworkInfo's own rules decide (today a
 * replace never crosses modules, and only two nodes of one kind merge).
 */
public record CrossModuleMerge(boolean replace, MergePolicy policy, String label) {
    /** What can be done with the two nodes, and when nothing can, why (NetworkInfo's refusals). */
    record Options(List<CrossModuleMerge> choices, String whyNone) {
    }

    static Options possible(NetworkInfo network, NodeRef first, NodeRef second) {
        List<CrossModuleMerge> choices = new ArrayList<>();
        Set<String> refusals = new LinkedHashSet<>();
        for (CrossModuleMerge c : List.of(
                new CrossModuleMerge(false, MergePolicy.FIRST, "Merge, keep " + first.node() + "'s parameters"),
                new CrossModuleMerge(false, MergePolicy.SECOND, "Merge, keep " + second.node() + "'s parameters"),
                new CrossModuleMerge(false, MergePolicy.BOTH, "Merge, keep both"),
                new CrossModuleMerge(true, null, "Replace " + second.node() + " by " + first.node()))) {
            try {
                NetworkInfo trial = network.copy();
                if (c.replace()) {
                    trial.replaceNode(second, first);
                } else {
                    trial.mergeNodes(first, second, c.policy());
                }
                choices.add(c);
            } catch (EditRefusedException e) {
                refusals.add(e.getMessage());
            }
        }
        return new Options(choices, String.join("; ", refusals));
    }

    static CrossModuleMerge ask(HiWindow owner, NodeRef first, NodeRef second, List<CrossModuleMerge> offered) {
        List<String> options = new ArrayList<>();
        offered.forEach(c -> options.add(c.label()));
        options.add("Cancel");
        int i = JOptionPane.showOptionDialog(owner, "Make " + first + " and " + second + " one node?",
                "Merge or Replace", JOptionPane.DEFAULT_OPTION, JOptionPane.QUESTION_MESSAGE, null,
                options.toArray(), options.get(Math.min(2, offered.size() - 1)));
        return i >= 0 && i < offered.size() ? offered.get(i) : null;
    }
}
