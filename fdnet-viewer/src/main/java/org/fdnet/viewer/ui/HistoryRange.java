package org.fdnet.viewer.ui;

import java.time.LocalDate;
import java.time.LocalTime;
import java.time.ZoneId;
import java.time.format.DateTimeParseException;

/**
 * The time range typed in the viewer's history field: {@code 60} (the last 60 s before {@code newest}),
 * or two clock times of the same day {@code 08:09:30-08:10:15} (seconds may have a fraction). Answers
 * {@code {from, to}} in µs since the epoch, or throws {@link IllegalArgumentException} saying what it
 * expected.
 */
final class HistoryRange {
    private HistoryRange() {
    }

    static long[] parse(String text, long newestMicros, ZoneId zone) {
        String t = text.trim();
        int dash = t.indexOf('-', 1);
        if (dash < 0) {
            double seconds;
            try {
                seconds = Double.parseDouble(t);
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException(expected(t));
            }
            if (!(seconds > 0)) {
                throw new IllegalArgumentException("history '" + t + "': the number of seconds must be above 0");
            }
            return new long[] {newestMicros - (long) (seconds * 1e6), newestMicros};
        }
        try {
            LocalDate day = java.time.Instant.ofEpochSecond(newestMicros / 1_000_000).atZone(zone).toLocalDate();
            long from = micros(day, LocalTime.parse(t.substring(0, dash).trim()), zone);
            long to = micros(day, LocalTime.parse(t.substring(dash + 1).trim()), zone);
            if (to <= from) {
                throw new IllegalArgumentException("history '" + t + "': the end must be after the start");
            }
            return new long[] {from, to};
        } catch (DateTimeParseException e) {
            throw new IllegalArgumentException(expected(t));
        }
    }

    private static long micros(LocalDate day, LocalTime time, ZoneId zone) {
        var instant = day.atTime(time).atZone(zone).toInstant();
        return instant.getEpochSecond() * 1_000_000L + instant.getNano() / 1000;
    }

    private static String expected(String t) {
        return "history '" + t + "': expected seconds (60 = the last minute) or clock times 08:09:30-08:10:15";
    }
}
