package org.fdnet.event.client;

/**
 * A snapshot of a {@link LoggerClient}: events accepted, acknowledged as committed by the logger, held in
 * memory, held in the journal (count and bytes), and lost because even the journal was full.
 */
public record ClientStatus(boolean connected, long accepted, long acked, long inMemory, long inJournal,
                           long journalBytes, long lost) {
}
