package org.fdnet.corba;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.fdnet.corba.idl.Value;
import org.fdnet.corba.idl.ValueBatch;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

class InboundLinkTest {
    private static final NodeRef MAP = new NodeRef("main", "map");
    private final DataOnlyNetwork network = new DataOnlyNetwork();
    private final List<Object> seen = new ArrayList<>();
    private final List<String> origins = new ArrayList<>();
    private InboundLink link;

    @BeforeEach
    void setUp() {
        network.create(MAP, NodeInfo.data("map", "LongData"));
        network.observe(MAP, (v, origin) -> {
            seen.add(v);
            origins.add(origin);
        });
        link = new InboundLink(7, MAP, "flyer", network);
    }

    @Test
    void shouldHoldBackABatchThatOvertookAnEarlierOne() {
        link.deliver(batch(0, 0, 1));
        long expectedAfterOvertaker = link.deliver(batch(4, 4, 5));
        assertThat(expectedAfterOvertaker).isEqualTo(2);
        assertThat(seen).containsExactly(0L, 1L);

        long expected = link.deliver(batch(2, 2, 3));

        assertThat(expected).isEqualTo(6);
        assertThat(seen).containsExactly(0L, 1L, 2L, 3L, 4L, 5L);
    }

    @Test
    void shouldSkipValuesAlreadyAppliedWhenTheSenderResends() {
        link.deliver(batch(10, 10, 11, 12));
        long expected = link.deliver(batch(11, 11, 12, 13, 14));

        assertThat(expected).isEqualTo(15);
        assertThat(seen).containsExactly(10L, 11L, 12L, 13L, 14L);
    }

    @Test
    void shouldMarkInjectedValuesWithTheHostTheyCameFrom() {
        link.deliver(batch(0, 42));

        assertThat(origins).containsExactly("flyer");
        assertThat(link.applied()).isEqualTo(1);
    }

    private static ValueBatch batch(long firstSeq, long... values) {
        Value[] encoded = new Value[values.length];
        for (int i = 0; i < values.length; i++) {
            encoded[i] = ValueCodec.encode(values[i]);
        }
        return new ValueBatch(7, firstSeq, encoded);
    }
}
