/**
 * The network state logger (Part 4): receiver server, indexed event cache, batch writer to PostgreSQL,
 * sender server for viewers, configuration panel.
 */
package org.fdnet.logger;
