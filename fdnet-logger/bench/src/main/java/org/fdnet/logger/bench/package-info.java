/**
 * The logger's benchmarks behind {@code fdnet bench logger}: producer processes, the raw COPY baseline, the batch-
 * size sweep and the report against targets.
 */
package org.fdnet.logger.bench;
