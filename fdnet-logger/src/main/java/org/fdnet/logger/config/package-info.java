/**
 * The logger's configuration: {@link org.fdnet.logger.config.LoggerSetting} names every parameter of the
 * thesis's panels (database, writer, receiver, sender, memory and priority) in one place;
 * {@link org.fdnet.logger.config.LoggerConfig} validates them and is sealed once the logger starts.
 *
 * <pre>
 *   file (LoggerConfigFile) ─┐
 *   command line options  ───┼──▶ LoggerConfig.set (validated) ──seal()──▶ NetworkStateLogger
 *   config panel (ui)     ───┘
 * </pre>
 */
package org.fdnet.logger.config;
