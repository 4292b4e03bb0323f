/**
 * The Human Interface: graphical and text-based network editor and live control of a running network.
 * Part 6 of the plan fills this module; it holds no code yet and nothing here claims to work.
 */
package org.fdnet.hi;
