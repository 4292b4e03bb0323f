package org.fdnet.event.client;

/**
 * A snapshot of a {@link LoggerClient}: events accepted, acknowledged as committed by the logger, held in
 * memory, held in the journal (count and bytes), and lost because even the journal was full.
 *
 * @param connected    whether the client is connected to the logger now
 * @param accepted     events accepted since the client started
 * @param acked        events the logger has confirmed as committed to its database
 * @param inMemory     events held in memory, sent or not
 * @param inJournal    events held in the spill journal
 * @param journalBytes the journal's size on disk
 * @param lost         events dropped because the journal was full
 */
public record ClientStatus(boolean connected, long accepted, long acked, long inMemory, long inJournal,
                           long journalBytes, long lost) {
}
