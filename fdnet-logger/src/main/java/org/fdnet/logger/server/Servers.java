package org.fdnet.logger.server;

import java.io.IOException;
import org.fdnet.logger.cache.EventCache;
import org.fdnet.logger.config.LoggerConfig;
import org.fdnet.logger.store.QueryPriority;
import org.fdnet.logger.store.SourceDirectory;

/** Builds the two servers: each is the same server and factory with its own connection class. */
public final class Servers {
    private Servers() {
    }

    public static TcpServer receiver(LoggerConfig config, EventCache cache, SourceDirectory directory, QueryPriority queries)
            throws IOException {
        RunOwners owners = new RunOwners();
        int maxFrame = config.maxFrameBytes();
        return new TcpServer("receiver", config.receiverAddress(), config.receiverPort(),
                new ConnectionFactory("receiver", config.receiverMaxClients(),
                        s -> new ReceiverConnection(s, maxFrame, cache, directory, owners, queries)));
    }

    public static TcpServer sender(LoggerConfig config, ViewerService viewers) throws IOException {
        int maxFrame = config.maxFrameBytes();
        return new TcpServer("sender", config.senderAddress(), config.senderPort(),
                new ConnectionFactory("sender", config.senderMaxClients(), s -> new SenderConnection(s, maxFrame, viewers, config.priorityEnabled()),
                        config.priorityEnabled() ? Thread.MAX_PRIORITY : Thread.NORM_PRIORITY));
    }
}
