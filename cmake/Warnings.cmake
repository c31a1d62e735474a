# The project's warning flags, in one place. Warnings are errors everywhere.
set(ZLINE_WARNINGS -Wall -Wextra -Werror -pedantic -Wshadow -Wcast-align -Wundef
    -Wstrict-prototypes -Wmissing-prototypes)
# core/ is also -Wconversion clean: every narrowing there is explicit.
set(ZLINE_CORE_WARNINGS ${ZLINE_WARNINGS} -Wconversion -Wsign-conversion)
