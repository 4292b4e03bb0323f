package org.fdnet.netinfo;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.List;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** The positioned inserts the editor's undo uses to put a deleted module, node or connection back at its place. */
class NetworkInfoPositionedInsertTest {
    private NetworkInfo network;
    private NodeRef a;
    private NodeRef b;
    private NodeRef r;

    @BeforeEach
    void build() {
        network = new NetworkInfo("n");
        a = network.addNode("main", NodeInfo.data("a", "D"));
        b = network.addNode("main", NodeInfo.data("b", "D"));
        r = network.addNode("main", NodeInfo.relation("r", "R"));
        network.addConnection("main", ConnectionInfo.reader(a, r));
        network.addConnection("main", ConnectionInfo.writer(r, b));
        network.addModule("M1", true);
        network.addModule("M2", false);
    }

    @Test
    void shouldPutADeletedNodeBackAtItsPlaceAndEqualTheOriginal() {
        NetworkInfo before = network.copy();
        NodeInfo doomed = network.node(a);
        List<LinkedConnection> connections = network.connectionsOf(a);
        network.deleteNode(a);
        network.addNode("main", doomed, 0);
        network.addConnection("main", connections.get(0).connection(), 0);
        assertThat(network).isEqualTo(before);
        assertThat(network.descendants(a)).contains(r, b);
    }

    @Test
    void shouldPutADeletedModuleBackAtItsPlace() {
        NetworkInfo before = network.copy();
        network.deleteModule("M1");
        network.addModule("M1", true, 1);
        assertThat(network).isEqualTo(before);
        assertThat(network.modules()).extracting(ModuleInfo::name).containsExactly("main", "M1", "M2");
    }

    @Test
    void shouldRefuseAPositionOutsideTheListAndChangeNothing() {
        NetworkInfo before = network.copy();
        assertThatThrownBy(() -> network.addNode("main", NodeInfo.data("c", "D"), 4)).isInstanceOf(EditRefusedException.class);
        assertThatThrownBy(() -> network.addModule("M3", true, -1)).isInstanceOf(EditRefusedException.class);
        assertThatThrownBy(() -> network.addConnection("main", ConnectionInfo.reader(b, r), 3)).isInstanceOf(EditRefusedException.class);
        assertThat(network).isEqualTo(before);
    }

    @Test
    void shouldRefuseAPositionedDuplicateConnectionOrNodeLikeThePlainAdd() {
        assertThatThrownBy(() -> network.addConnection("M1", ConnectionInfo.reader(a, r), 0))
                .isInstanceOf(EditRefusedException.class).hasMessageContaining("duplicate");
        assertThatThrownBy(() -> network.addNode("main", NodeInfo.data("a", "D"), 0))
                .isInstanceOf(EditRefusedException.class).hasMessageContaining("already has");
    }
}
