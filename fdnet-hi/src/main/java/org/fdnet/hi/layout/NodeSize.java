package org.fdnet.hi.layout;

/** A node's width and height on the drawing. */
public record NodeSize(double width, double height) {
}
