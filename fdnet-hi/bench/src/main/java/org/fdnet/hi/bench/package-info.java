/**
 * The editor's benchmark behind {@code fdnet bench hi}: opening and laying out large networks in a fresh JVM
 * beside bare ELK.
 */
package org.fdnet.hi.bench;
