package org.fdnet.roq.bridge;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Stream;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.ConnectionKind;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.fdnet.roq.node.RoqSensor;
import org.junit.jupiter.api.Test;

/**
 * The sensing rule: RoQ's Relations act on what a real RoQ could sense. Ground truth — the body's position and
 * the centre of mass, which only the simulator knows — is there for measurement and tests; no Relation in any
 * shipped network may read it.
 */
class GroundTruthRuleTest {
    private static final Set<String> GROUND_TRUTH = Set.of("body_position", "centre_of_mass");

    @Test
    void shouldLetNoRelationInAnyShippedNetworkReadGroundTruth() throws Exception {
        List<String> networks = new ArrayList<>();
        List<String> offences = new ArrayList<>();
        Set<String> sensorsRead = new TreeSet<>();
        try (Stream<Path> files = Files.list(Path.of("..", "networks"))) {
            for (Path file : files.filter(f -> f.toString().endsWith(".fdn")).sorted().toList()) {
                networks.add(file.getFileName().toString());
                NetworkInfo net = NetworkRepository.load(file);
                for (ModuleInfo module : net.modules()) {
                    for (ConnectionInfo c : module.connections()) {
                        NodeInfo data = c.kind() == ConnectionKind.READER ? net.node(c.data()) : null;
                        if (data != null && RoqSensor.class.getName().equals(data.className())) {
                            String channel = String.valueOf(data.parameter("channel")).strip();
                            sensorsRead.add(channel);
                            if (GROUND_TRUTH.contains(channel)) {
                                offences.add(file.getFileName() + ": " + c.relation() + " reads " + c.data());
                            }
                        }
                    }
                }
            }
        }
        assertThat(networks).as("shipped networks").contains("roq-walk.fdn", "roq-rubble.fdn");
        assertThat(sensorsRead).as("sensor channels the Relations read")
                .contains("attitude", "joint_angles", "foot_forces", "imu_gyro");
        assertThat(offences).as("Relations reading ground truth").isEmpty();
    }
}
