/**
 * The logger protocol: versioned, length-prefixed binary frames shared by the core's logger client, the
 * logger and the viewers (specified in {@code docs/reference/protocol.md}).
 *
 * <pre>
 *   NetworkEvent ──EventCodec──▶ FrameWriter ──u32 length · u8 type · payload──▶ socket
 *   socket ──FrameReader (length ≤ max, whole frame or "truncated")──▶ Frame ──EventCodec──▶ NetworkEvent
 *   a core's EVENTS frame ──EventsFrame.check (every event, no trailing bytes)──▶ the receiver takes its events
 *   a viewer's request ──ViewerRequest.write──▶ logger ──ViewerRequest.read (checked whole)──▶ sender server
 *
 *   a Data's value: TypedValue ──ValueCodec (u8 type, then binary: f64, i64, ...)──▶ the same TypedValue
 *   a plot's history: logger ──HISTORY_CHUNK──▶ HistoryColumns.appendAll ──▶ times[] · sources[] · numbers
 *       (8 bytes each, read in place; text and events on demand)
 * </pre>
 *
 * Every read is bounds-checked and fails with a {@link org.fdnet.event.wire.ProtocolException} that names
 * what was wrong; servers log it and close that one connection.
 */
package org.fdnet.event.wire;
