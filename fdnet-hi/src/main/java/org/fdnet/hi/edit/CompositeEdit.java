package org.fdnet.hi.edit;

import java.util.ArrayList;
import java.util.List;
import org.fdnet.netinfo.EditRefusedException;

/**
 * Several edits as one step. If one is refused, those already applied are taken back before the
 * refusal goes on, so the step as a whole changes nothing.
 */
record CompositeEdit(List<ReversibleEdit> parts) implements ReversibleEdit {

    static ReversibleEdit of(List<ReversibleEdit> parts) {
        return parts.size() == 1 ? parts.get(0) : new CompositeEdit(List.copyOf(parts));
    }

    @Override
    public ReversibleEdit applyTo(EditTarget target) {
        List<ReversibleEdit> inverses = new ArrayList<>();
        try {
            for (ReversibleEdit part : parts) {
                inverses.add(0, part.applyTo(target));
            }
        } catch (EditRefusedException refused) {
            for (ReversibleEdit inverse : inverses) {
                inverse.applyTo(target);
            }
            throw refused;
        }
        return new CompositeEdit(inverses);
    }
}
