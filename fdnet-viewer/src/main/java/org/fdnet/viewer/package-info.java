/**
 * The Network State Viewer: live and historical plots of node values, a client of the logger's sender
 * server. Part 6 of the plan fills this module; it holds no code yet and nothing here claims to work.
 */
package org.fdnet.viewer;
