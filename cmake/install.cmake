# Install rules, the man page and CPack: filled in by the next commit.
