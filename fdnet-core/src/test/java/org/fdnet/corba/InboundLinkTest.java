package org.fdnet.corba;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicLong;
import org.fdnet.corba.idl.Value;
import org.fdnet.corba.idl.ValueBatch;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

class InboundLinkTest {
    private static final NodeRef MAP = new NodeRef("main", "map");
    private static final String STREAM = "flyer#1#7";
    private final DataOnlyNetwork network = new DataOnlyNetwork();
    private final List<Object> values = new ArrayList<>();
    private final List<String> origins = new ArrayList<>();
    private final Map<String, AtomicLong> appliedByStream = new ConcurrentHashMap<>();
    private InboundLink link;

    @BeforeEach
    void setUp() {
        network.create(MAP, NodeInfo.data("map", "LongData"));
        network.observe(MAP, (v, fromHost, origin) -> {
            values.add(v);
            origins.add(fromHost);
        });
        link = new InboundLink(7, MAP, "flyer", network, appliedByStream);
    }

    @Test
    void shouldHoldBackABatchThatOvertookAnEarlierOne() {
        link.deliver(batch(0, 0, 1));
        long expectedAfterOvertaker = link.deliver(batch(4, 4, 5));
        assertThat(expectedAfterOvertaker).isEqualTo(2);
        assertThat(values).containsExactly(0L, 1L);

        long expected = link.deliver(batch(2, 2, 3));

        assertThat(expected).isEqualTo(6);
        assertThat(values).containsExactly(0L, 1L, 2L, 3L, 4L, 5L);
    }

    @Test
    void shouldSkipValuesAlreadyAppliedWhenTheSenderResends() {
        link.deliver(batch(10, 10, 11, 12));
        long expected = link.deliver(batch(11, 11, 12, 13, 14));

        assertThat(expected).isEqualTo(15);
        assertThat(values).containsExactly(10L, 11L, 12L, 13L, 14L);
    }

    @Test
    void shouldNotApplyAgainAValueOfAStreamItAlreadyAppliedThroughADeadRelay() {
        link.deliver(batch(0, 0, 1, 2));
        // The relay died and its successor opened the link again from sequence 0, carrying values of the
        // same origin stream: 1 and 2 were applied before, 3 is new.
        InboundLink again = new InboundLink(7, MAP, "crawler", network, appliedByStream);
        Value[] resent = {ValueCodec.encode(1L), ValueCodec.encode(2L), ValueCodec.encode(3L)};

        long expected = again.deliver(new ValueBatch(7, 0, STREAM, 1, resent));

        assertThat(expected).isEqualTo(3);
        assertThat(again.duplicates()).isEqualTo(2);
        assertThat(values).containsExactly(0L, 1L, 2L, 3L);
        assertThat(appliedByStream.get(STREAM)).hasValue(3L);
    }

    @Test
    void shouldMarkInjectedValuesWithTheHostAndStreamTheyCameFrom() {
        List<ValueOrigin> current = new ArrayList<>();
        network.observe(MAP, (v, fromHost, origin) -> current.add(origin));

        link.deliver(batch(0, 42));

        assertThat(origins).containsExactly("flyer");
        assertThat(current).containsExactly(new ValueOrigin(STREAM, 0));
        assertThat(link.applied()).isEqualTo(1);
    }

    /** Values of the origin stream numbered like the link's own sequence. */
    private static ValueBatch batch(long firstSeq, long... longs) {
        Value[] encoded = new Value[longs.length];
        for (int i = 0; i < longs.length; i++) {
            encoded[i] = ValueCodec.encode(longs[i]);
        }
        return new ValueBatch(7, firstSeq, STREAM, firstSeq, encoded);
    }
}
