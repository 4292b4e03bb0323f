/**
 * Our own FDNet nodes, run beside RoQ's in networks/lab-walk.fdn (module Lab):
 *
 * <pre>
 *   attitude (RoQ's inclinometer) ──┐
 *   gait feet (the crawl gait) ─────┴─▶ PitchDamper ──▶ Lab/pitch correction (FootCorrection: refuses |z| &gt; bound)
 *                                                          ──▶ Integration/integrate ──▶ feet ──▶ Legs ──▶ joints
 * </pre>
 *
 * Unload module Lab and the integration leaves the correction out: RoQ walks on without it.
 */
package ${package};
