package org.fdnet.apart;

import java.util.List;

/** Tries to make a rig and prints what refused it: run by the tests as a user that is not root. */
public final class NotRootProbe {
    private NotRootProbe() {
    }

    public static void main(String[] args) {
        try (ApartRig rig = ApartRig.create("fdnrignotroot", List.of("a"))) {
            System.out.println("made " + rig.rigNamespace());
        } catch (IllegalStateException e) {
            System.out.println(e.getMessage());
        }
    }
}
