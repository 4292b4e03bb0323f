/**
 * {@code fdnet apart}: the apart rig ({@link org.fdnet.apart.ApartRig}) for people. {@code up} makes it and keeps it
 * until Ctrl-C; {@code exec}, {@code fault}, {@code status} and {@code down} find the rig that is up by its name
 * (its namespaces {@code NAME-PID…}) from other terminals; {@code sweep} removes what a killed one left.
 */
package org.fdnet.apart.cli;
