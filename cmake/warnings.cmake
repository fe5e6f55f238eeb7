# Warning flags every project target compiles with; any warning fails the build.
set(STEPDANCE_STRICT_WARNINGS -Wall -Wextra -Werror -Wundef -Wimplicit-fallthrough -Wshadow)
