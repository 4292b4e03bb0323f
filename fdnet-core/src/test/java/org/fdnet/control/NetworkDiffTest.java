package org.fdnet.control;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.EditRefusedException;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;
import org.junit.jupiter.api.Test;

class NetworkDiffTest {
    private static final String DOUBLE = "org.fdnet.runtime.library.DoubleData";
    private static final String EXPR = "org.fdnet.runtime.library.Expression";

    private static NodeRef ref(String text) {
        return NodeRef.parse(text, "main");
    }

    /** Balance/keep reads Balance/tilt and writes Legs/targets; Legs/ik reads Legs/targets. */
    private static NetworkInfo robot() {
        NetworkInfo n = new NetworkInfo("robot");
        n.addModule("Balance", true);
        n.addModule("Legs", true);
        n.addNode("Balance", NodeInfo.data("tilt", DOUBLE));
        n.addNode("Balance", NodeInfo.relation("keep", EXPR, Parameter.named("expression", "in0"),
                Parameter.named("margin", "0.02")));
        n.addNode("Legs", NodeInfo.data("targets", DOUBLE));
        n.addNode("Legs", NodeInfo.relation("ik", EXPR, Parameter.named("expression", "in0")));
        n.addNode("Legs", NodeInfo.data("angles", DOUBLE));
        n.addConnection("Balance", ConnectionInfo.reader(ref("Balance/tilt"), ref("Balance/keep")));
        n.addConnection("Balance", ConnectionInfo.writer(ref("Balance/keep"), ref("Legs/targets")));
        n.addConnection("Legs", ConnectionInfo.reader(ref("Legs/targets"), ref("Legs/ik")));
        n.addConnection("Legs", ConnectionInfo.writer(ref("Legs/ik"), ref("Legs/angles")));
        return n;
    }

    @Test
    void shouldBeEmptyForTwoEqualDefinitions() {
        NetworkDiff diff = NetworkDiff.between(robot(), robot());
        assertThat(diff.isEmpty()).isTrue();
        assertThat(diff.toString()).isEqualTo("no changes");
    }

    @Test
    void shouldListAddedRemovedAndChangedNodesParametersAndConnectionsReadably() {
        NetworkInfo base = robot();
        NetworkInfo edited = base.copy();
        edited.addModule("Walk", false);
        edited.addNode("Walk", NodeInfo.data("gain", DOUBLE));
        edited.setParameters(ref("Balance/keep"), java.util.List.of(Parameter.named("expression", "in0"),
                Parameter.named("margin", "0.03")));
        edited.deleteConnection("Legs", ConnectionInfo.writer(ref("Legs/ik"), ref("Legs/angles")));
        edited.deleteNode(ref("Balance/tilt"));

        NetworkDiff diff = NetworkDiff.between(base, edited);

        assertThat(diff.entries()).extracting(NetworkDiff.Entry::text).containsExactlyInAnyOrder(
                "+ module Walk",
                "+ node Walk/gain",
                "~ Balance/keep parameter margin 0.02 → 0.03",
                "- node Balance/tilt",
                "- connection Legs/ik → Legs/angles");
        NetworkDiff.Entry param = diff.entries().stream().filter(e -> e.change() == NetworkDiff.Change.CHANGED)
                .findFirst().orElseThrow();
        assertThat(param.subject()).isEqualTo("Balance/keep");
        assertThat(param.detail()).isEqualTo("parameter margin 0.02 → 0.03");
    }

    @Test
    void shouldTurnTheBaseIntoTheEditedDefinition() {
        NetworkInfo base = robot();
        NetworkInfo edited = base.copy();
        edited.addModule("Walk", false);
        edited.addNode("Walk", NodeInfo.relation("step", EXPR, Parameter.named("expression", "in0 * 2")));
        edited.addConnection("Walk", ConnectionInfo.reader(ref("Legs/angles"), ref("Walk/step")));
        edited.deleteNode(ref("Balance/tilt"));
        edited.updateNode(ref("Legs/ik"), new NodeInfo(org.fdnet.netinfo.NodeKind.RELATION, "ik", "localhost", "",
                EXPR, java.util.List.of(Parameter.named("expression", "in0 + 1"))));
        edited.deleteModule("Balance");

        NetworkInfo target = base.copy();
        NetworkDiff.between(base, edited).asEdit().applyTo(target);

        assertThat(NetworkDiff.between(target, edited).isEmpty()).isTrue();
        assertThat(target.node(ref("Legs/ik")).parameter("expression")).isEqualTo("in0 + 1");
        assertThat(target.module("Balance")).isNull();
    }

    @Test
    void shouldKeepWhatTheRunningNetworkBuiltItselfMeanwhile() {
        NetworkInfo base = robot();
        NetworkInfo edited = base.copy();
        edited.setParameters(ref("Balance/keep"), java.util.List.of(Parameter.named("expression", "in0"),
                Parameter.named("margin", "0.03")));
        NetworkInfo running = base.copy();
        // a Relation pasted a node and connected it while the operator edited
        running.addNode("Legs", NodeInfo.data("pasted", DOUBLE));
        running.addConnection("Legs", ConnectionInfo.writer(ref("Legs/ik"), ref("Legs/pasted")));

        NetworkDiff.between(base, edited).asEdit().applyTo(running);

        assertThat(running.node(ref("Balance/keep")).parameter("margin")).isEqualTo("0.03");
        assertThat(running.node(ref("Legs/pasted"))).isNotNull();
        assertThat(running.connectionsOf(ref("Legs/pasted"))).hasSize(1);
    }

    @Test
    void shouldRefuseNamingTheConflictWhenAParameterChangedMeanwhile() {
        NetworkInfo base = robot();
        NetworkInfo edited = base.copy();
        edited.setParameters(ref("Balance/keep"), java.util.List.of(Parameter.named("expression", "in0"),
                Parameter.named("margin", "0.03")));
        NetworkInfo running = base.copy();
        running.setParameters(ref("Balance/keep"), java.util.List.of(Parameter.named("expression", "in0"),
                Parameter.named("margin", "0.05")));

        assertThatThrownBy(() -> NetworkDiff.between(base, edited).asEdit().applyTo(running))
                .isInstanceOf(EditRefusedException.class)
                .hasMessage("Balance/keep: parameter margin is 0.05 in the running network, not 0.02 as when the edit began");
    }

    @Test
    void shouldRefuseToRemoveWhatTheRunningNetworkNoLongerHasAndToAddWhatItAlreadyHas() {
        NetworkInfo base = robot();
        NetworkInfo removing = base.copy();
        removing.deleteConnection("Legs", ConnectionInfo.reader(ref("Legs/targets"), ref("Legs/ik")));
        NetworkInfo running = base.copy();
        running.deleteConnection("Legs", ConnectionInfo.reader(ref("Legs/targets"), ref("Legs/ik")));
        assertThatThrownBy(() -> NetworkDiff.between(base, removing).asEdit().applyTo(running))
                .isInstanceOf(EditRefusedException.class)
                .hasMessageContaining("cannot remove connection Legs/targets → Legs/ik: the running network no longer has it");

        NetworkInfo adding = base.copy();
        adding.addNode("main", NodeInfo.data("speed", DOUBLE));
        NetworkInfo running2 = base.copy();
        running2.addNode("main", NodeInfo.data("speed", DOUBLE));
        assertThatThrownBy(() -> NetworkDiff.between(base, adding).asEdit().applyTo(running2))
                .isInstanceOf(EditRefusedException.class)
                .hasMessageContaining("cannot add node main/speed: the running network already has a node of that name");
    }

    @Test
    void shouldShowAClassChangeAndAModuleLoadFlag() {
        NetworkInfo base = robot();
        NetworkInfo edited = base.copy();
        NodeInfo angles = edited.node(ref("Legs/angles"));
        edited.updateNode(ref("Legs/angles"), new NodeInfo(angles.kind(), angles.name(), angles.host(), angles.path(),
                "org.fdnet.runtime.library.DoublesData", angles.parameters()));
        edited.setLoadAtStart("Legs", false);

        assertThat(NetworkDiff.between(base, edited).entries()).extracting(NetworkDiff.Entry::text).containsExactly(
                "~ module Legs not loaded at start",
                "~ Legs/angles class " + DOUBLE + " → org.fdnet.runtime.library.DoublesData");
    }
}
