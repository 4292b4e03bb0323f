package org.fdnet.viewer.data;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.ValueType;
import org.fdnet.viewer.ui.CsvExport;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class SeriesTest {
    @TempDir
    Path folder;

    @Test
    void shouldReadTheValueHeldAtAnInstantNotOneWrittenLater() {
        Series s = new Series("Balance/margin", "m");
        s.append(1000, 0.1);
        s.append(2000, 0.2);
        assertThat(s.heldAt(999)).as("before its first value").isNull();
        assertThat(s.heldAt(1000).value()).isEqualTo(0.1);
        assertThat(s.heldAt(1999).value()).as("held until written again, though 2000 is nearer").isEqualTo(0.1);
        assertThat(s.heldAt(5000).value()).isEqualTo(0.2);
    }

    @Test
    void shouldKeepSamplesInOrderAndAnswerRangesAndNearest() {
        Series s = new Series("Arm/Joint", "rad");
        for (int i = 0; i < 5000; i++) {
            s.append(1000 + i * 10L, i);
        }
        Series.Samples r = s.range(1100, 1200);
        assertThat(r.size()).isEqualTo(11);
        assertThat(r.values()[0]).isEqualTo(10);
        assertThat(s.nearest(1104).value()).isEqualTo(10);
        assertThat(s.nearest(1106).value()).isEqualTo(11);
        assertThat(s.size()).isEqualTo(5000);
    }

    @Test
    void shouldSplitVectorsIntoOneSeriesPerComponentAndSkipStrings() {
        PlotData d = new PlotData();
        d.track(7, "Balance/candidate", "");
        d.accept(new DataValueEvent(7, 1, ValueType.DOUBLES, "0.1 0.2 0.3"));
        d.accept(new DataValueEvent(7, 2, ValueType.STRING, "hello"));
        d.accept(new DataValueEvent(8, 3, ValueType.DOUBLE, "1.0"));
        assertThat(d.series()).extracting(Series::name)
                .containsExactly("Balance/candidate[0]", "Balance/candidate[1]", "Balance/candidate[2]");
        assertThat(d.ignoredEvents()).isEqualTo(2);
        assertThat(NodeSelection.parse("Pose/stability margin[m]")).isEqualTo(new NodeSelection("Pose/stability margin", "m"));
    }

    @Test
    void shouldExportTheSamplesOfTheRangeAsCsv() throws Exception {
        Series a = new Series("Pose/pitch", "rad");
        Series b = new Series("a, \"b\"", "");
        for (int i = 0; i < 10; i++) {
            a.append(i, i * 0.5);
            b.append(i, -i);
        }
        Path csv = folder.resolve("out.csv");
        assertThat(CsvExport.write(csv, List.of(a, b), 2, 4)).isEqualTo(6);
        assertThat(Files.readAllLines(csv)).containsExactly("series,unit,time_us,value", "Pose/pitch,rad,2,1.0",
                "Pose/pitch,rad,3,1.5", "Pose/pitch,rad,4,2.0", "\"a, \"\"b\"\"\",,2,-2.0", "\"a, \"\"b\"\"\",,3,-3.0",
                "\"a, \"\"b\"\"\",,4,-4.0");
    }
}
