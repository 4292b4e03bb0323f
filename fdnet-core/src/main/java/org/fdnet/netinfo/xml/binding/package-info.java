/**
 * JAXB bindings of the .fdn format, one class per element of {@code dtd/cnet.dtd}, written by hand
 * because the format is a DTD (not a schema). They carry file positions ({@link
 * org.fdnet.netinfo.xml.binding.Located}) and no rules: {@code NetworkFileReader} turns them into a
 * checked {@code NetworkInfo}, {@code NetworkFileWriter} builds them from one.
 */
package org.fdnet.netinfo.xml.binding;
