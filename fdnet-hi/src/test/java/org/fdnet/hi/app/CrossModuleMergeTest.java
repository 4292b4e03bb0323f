package org.fdnet.hi.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import org.fdnet.netinfo.MergePolicy;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.junit.jupiter.api.Test;

/** For two nodes of different modules the editor offers only what NetworkInfo would carry out. */
class CrossModuleMergeTest {
    private static final Path ARMS = Path.of("..", "networks", "arms.fdn");

    @Test
    void shouldOfferTheThreeMergesButNoReplaceForTwoDatasOfDifferentModules() throws Exception {
        NetworkInfo arms = NetworkRepository.load(ARMS);
        CrossModuleMerge.Options options = CrossModuleMerge.possible(arms, new NodeRef("LeftArm", "Shoulder"),
                new NodeRef("RightArm", "Shoulder"));
        assertThat(options.choices()).extracting(CrossModuleMerge::replace).containsOnly(false);
        assertThat(options.choices()).extracting(CrossModuleMerge::policy)
                .containsExactly(MergePolicy.FIRST, MergePolicy.SECOND, MergePolicy.BOTH);
        assertThat(arms).as("only copies were tried").isEqualTo(NetworkRepository.load(ARMS));
    }

    @Test
    void shouldOfferNothingAndSayWhyForADataAndARelationOfDifferentModules() throws Exception {
        NetworkInfo arms = NetworkRepository.load(ARMS);
        CrossModuleMerge.Options options = CrossModuleMerge.possible(arms, new NodeRef("main", "Clock"),
                new NodeRef("LeftArm", "Plan"));
        assertThat(options.choices()).isEmpty();
        assertThat(options.whyNone()).contains("cannot merge main/Clock (a Data) with LeftArm/Plan (a Relation)",
                "replace works within one module");
    }
}
