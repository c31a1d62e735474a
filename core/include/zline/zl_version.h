/* SPDX-License-Identifier: MIT */
/*
 * zline's version: the one source of it. The top-level CMakeLists.txt reads
 * these three numbers for project(VERSION), so the CMake package, zline.pc
 * and this header always agree (the consumer test 'version' of
 * tests/consumer/run.sh checks it). What each version added: CHANGELOG.md.
 * Semantic versioning: a new MAJOR breaks the API; find_package(zline X.Y)
 * accepts any installed X.*.* at least X.Y.
 */
#ifndef ZLINE_VERSION_H
#define ZLINE_VERSION_H

#define ZL_VERSION_MAJOR 0
#define ZL_VERSION_MINOR 3
#define ZL_VERSION_PATCH 0

#define ZL_VERSION_STR2_(x) #x
#define ZL_VERSION_STR_(a, b, c) ZL_VERSION_STR2_(a) "." ZL_VERSION_STR2_(b) "." ZL_VERSION_STR2_(c)
/* "MAJOR.MINOR.PATCH" */
#define ZL_VERSION_STRING ZL_VERSION_STR_(ZL_VERSION_MAJOR, ZL_VERSION_MINOR, ZL_VERSION_PATCH)
/* One comparable number: MAJOR * 10000 + MINOR * 100 + PATCH. */
#define ZL_VERSION (ZL_VERSION_MAJOR * 10000 + ZL_VERSION_MINOR * 100 + ZL_VERSION_PATCH)

#endif /* ZLINE_VERSION_H */
