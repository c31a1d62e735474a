# SPDX-License-Identifier: MIT
# The project's warning flags, in one place. They are only ever used as
# PRIVATE compile options of zline's own targets: nothing here reaches a
# consumer's compiler. -Werror is on in zline's own builds (top level, CI);
# as a subproject (ZLINE_WARNINGS_AS_ERRORS defaults to OFF there) a newer
# compiler's new warning must not break someone else's firmware build.
set(ZLINE_WARNINGS -Wall -Wextra -pedantic -Wshadow -Wcast-align -Wundef
    -Wstrict-prototypes -Wmissing-prototypes)
if(ZLINE_WARNINGS_AS_ERRORS)
  list(APPEND ZLINE_WARNINGS -Werror)
endif()
# core/ is also -Wconversion clean: every narrowing there is explicit.
set(ZLINE_CORE_WARNINGS ${ZLINE_WARNINGS} -Wconversion -Wsign-conversion)
