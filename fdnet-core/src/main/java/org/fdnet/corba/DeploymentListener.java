package org.fdnet.corba;

/** What a distributed run tells its user: hosts lost and back, links broken and restored. */
public interface DeploymentListener {
    void hostLost(String host, String reason);

    /**
     * A lost host registered again and its share was re-created and re-wired.
     *
     * @param outageMillis  from noticing the loss to the host's return being noticed
     * @param rewireMillis  from noticing the return to every node and link of the host working again
     */
    void hostRecovered(String host, long outageMillis, long rewireMillis);

    void linkBroken(DeploymentPlan.Link link, String reason);

    void linkRestored(DeploymentPlan.Link link);

    /** Nothing to tell: for tests and the benchmark. */
    static DeploymentListener quiet() {
        return new DeploymentListener() {
            @Override
            public void hostLost(String host, String reason) {
            }

            @Override
            public void hostRecovered(String host, long outageMillis, long rewireMillis) {
            }

            @Override
            public void linkBroken(DeploymentPlan.Link link, String reason) {
            }

            @Override
            public void linkRestored(DeploymentPlan.Link link) {
            }
        };
    }
}
