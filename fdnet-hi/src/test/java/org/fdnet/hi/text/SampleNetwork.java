package org.fdnet.hi.text;

import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;
import org.fdnet.netinfo.ParameterType;

/**
 * The network the frames' tests edit: in main, Speed (Data, gain:long=3) ─read by─▶ Control (Relation)
 * ─writes─▶ Command (Data); in module Arm (not loaded at start), Angle ─▶ Servo, and Servo also reads main's Speed.
 */
public final class SampleNetwork {
    private SampleNetwork() {
    }

    public static final NodeRef SPEED = new NodeRef("main", "Speed");
    public static final NodeRef CONTROL = new NodeRef("main", "Control");
    public static final NodeRef COMMAND = new NodeRef("main", "Command");
    public static final NodeRef ANGLE = new NodeRef("Arm", "Angle");
    public static final NodeRef SERVO = new NodeRef("Arm", "Servo");

    public static NetworkInfo create() {
        NetworkInfo n = new NetworkInfo("robot");
        n.addNode("main", new NodeInfo(org.fdnet.netinfo.NodeKind.DATA, "Speed", "roq", "/opt/nodes",
                "fdnet.SpeedData", java.util.List.of(new Parameter("gain", ParameterType.LONG, "3"),
                Parameter.of("fast"))));
        n.addNode("main", NodeInfo.relation("Control", "fdnet.Control"));
        n.addNode("main", NodeInfo.data("Command", "fdnet.Command"));
        n.addConnection("main", ConnectionInfo.reader(SPEED, CONTROL));
        n.addConnection("main", ConnectionInfo.writer(CONTROL, COMMAND));
        n.addModule("Arm", false);
        n.addNode("Arm", NodeInfo.data("Angle", "fdnet.Angle"));
        n.addNode("Arm", NodeInfo.relation("Servo", "fdnet.Servo"));
        n.addConnection("Arm", ConnectionInfo.reader(ANGLE, SERVO));
        n.addConnection("Arm", ConnectionInfo.reader(SPEED, SERVO));
        return n;
    }
}
