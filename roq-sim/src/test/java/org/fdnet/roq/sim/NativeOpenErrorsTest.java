package org.fdnet.roq.sim;

import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The native open refuses bad figures with one message naming what and which (cell, period, array). */
class NativeOpenErrorsTest {
    @TempDir
    static Path dir;
    private static Path model;
    private static Heightfield terrain;

    @BeforeAll
    static void writeAFlatModel() throws IOException {
        RoqNativeLibrary.ensureLoaded();
        terrain = Heightfield.of(Course.flat());
        model = Files.writeString(dir.resolve("flat.xml"), MjcfWriter.write(Course.flat(), terrain, 0));
    }

    @Test
    void shouldNameTheFragileCellTheModelLacks() {
        double[] oneCell = NativeParameters.fragileFigures(
                java.util.List.of(new FragileCell(0.5, 0, 0.2, 0.2, 0.03, 40)));
        assertThatThrownBy(() -> open(oneCell, defaults()))
                .isInstanceOf(IllegalStateException.class).hasMessage("model lacks geom fragile_0 (fragile cell 0)");
    }

    @Test
    void shouldRefuseMoreCellsThanTheModelCanHold() {
        double[] figures = new double[NativeParameters.F_STRIDE * (Course.MAX_FRAGILE_CELLS + 1)];
        assertThatThrownBy(() -> open(figures, defaults()))
                .hasMessage((Course.MAX_FRAGILE_CELLS + 1) + " fragile cells, at most " + Course.MAX_FRAGILE_CELLS);
    }

    @Test
    void shouldRefuseCellFiguresThatAreNotWholeCells() {
        assertThatThrownBy(() -> open(new double[NativeParameters.F_STRIDE + 1], defaults()))
                .hasMessageContaining("fragile cell figures: 7 values, not a multiple of F_STRIDE 6");
    }

    @Test
    void shouldNameARangeSensorPeriodOfZero() {
        double[] params = defaults();
        params[NativeParameters.P_US_PERIOD] = 0;
        assertThatThrownBy(() -> open(new double[0], params))
                .hasMessageStartingWith("range sensor periods must be at least 1 tick")
                .hasMessageContaining("ultrasonic 0");
    }

    @Test
    void shouldNameADepthRowPeriodThatDoesNotDivideTheImage() {
        double[] params = defaults();
        params[NativeParameters.P_DEPTH_ROW_PERIOD] = 5;
        assertThatThrownBy(() -> open(new double[0], params))
                .hasMessage("depth row period 5 must divide the image width " + RoqGeometry.DEPTH_WIDTH);
    }

    @Test
    void shouldRefuseAParameterArrayOfTheWrongLength() {
        assertThatThrownBy(() -> open(new double[0], new double[NativeParameters.P_COUNT - 1]))
                .hasMessageContaining("parameter array of 43 values, P_COUNT is 44");
    }

    private static double[] defaults() {
        return NativeParameters.of(SimOptions.of(SimMode.STEPPED));
    }

    private static void open(double[] fragile, double[] params) {
        ByteBuffer block = ByteBuffer.allocateDirect(SharedBlockLayout.BLOCK_SIZE).order(ByteOrder.nativeOrder());
        long handle = RoqNative.open(model.toString(), terrain.normalised(), fragile, params, block);
        RoqNative.close(handle); // reached only when open wrongly succeeded; the assertion then fails
    }
}
