package org.fdnet.logger.cache;

import org.fdnet.event.NetworkEvent;

/**
 * One cached event as the panel's cache browser shows it: the event, whether it is already in the database
 * ({@code written}) and whether a viewer's monitor still waits for it ({@code monitored}: it cannot leave
 * memory until sent). A snapshot; the cache moves on.
 */
public record CacheEntry(NetworkEvent event, boolean written, boolean monitored) {
}
