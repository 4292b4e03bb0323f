package org.fdnet.logger.store;

import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.SQLException;
import java.util.Properties;

/** Where the logger's database is: a JDBC URL and credentials. Opening a connection is all it does. */
public record DatabaseTarget(String url, String user, String password) {

    public Connection open() throws SQLException {
        Properties p = new Properties();
        p.setProperty("user", user);
        if (password != null && !password.isEmpty()) {
            p.setProperty("password", password);
        }
        p.setProperty("connectTimeout", "5");
        p.setProperty("socketTimeout", "60");
        p.setProperty("tcpKeepAlive", "true");
        return DriverManager.getConnection(url, p);
    }

    @Override
    public String toString() {
        return url + " as " + user;
    }
}
