// Exists, but the fixture does not list it.
