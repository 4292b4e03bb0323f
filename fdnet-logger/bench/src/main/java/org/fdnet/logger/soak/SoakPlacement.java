package org.fdnet.logger.soak;

import java.util.List;
import org.fdnet.apart.ApartRig;

/**
 * Where the soak's processes run: all on this machine's loopback, or each on a host of its own in an {@link ApartRig}
 * (a network namespace with its own address), where faults can be put on its link. Off loopback the processes run
 * with {@code --insecure}: the soak checks delivery under faults, and its namespaces are reachable from this machine
 * only.
 */
interface SoakPlacement {
    /** The processes' names, each a host of the rig when apart. */
    List<String> PROCESSES = List.of("naming", "flyer", "crawler", "logger", "operator");

    /** The address process {@code name} listens on and is reached at. */
    String address(String name);

    /** What starts a command on process {@code name}'s host (empty: here). */
    List<String> launchPrefix(String name);

    /** {@code fdnet} options that let process {@code name} listen on {@link #address}. */
    List<String> bindOptions(String name);

    /** The rig, when apart; {@code null} on loopback. */
    ApartRig rig();

    /** Everything on 127.0.0.1. */
    static SoakPlacement loopback() {
        return new SoakPlacement() {
            @Override
            public String address(String name) {
                return "127.0.0.1";
            }

            @Override
            public List<String> launchPrefix(String name) {
                return List.of();
            }

            @Override
            public List<String> bindOptions(String name) {
                return List.of();
            }

            @Override
            public ApartRig rig() {
                return null;
            }
        };
    }

    /** Each process on its own host of {@code rig}. */
    static SoakPlacement apart(ApartRig rig) {
        return new SoakPlacement() {
            @Override
            public String address(String name) {
                return rig.address(name).getHostAddress();
            }

            @Override
            public List<String> launchPrefix(String name) {
                return rig.command(name, List.of());
            }

            @Override
            public List<String> bindOptions(String name) {
                return List.of("--bind", address(name), "--insecure");
            }

            @Override
            public ApartRig rig() {
                return rig;
            }
        };
    }
}
