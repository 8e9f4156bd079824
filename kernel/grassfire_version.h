// grassfire_version.h -- the library's version; CMakeLists.txt checks that project() says the same.
// Versions 0.x: a minor version may change the C++ API. File formats carry their own
// versions; CHANGELOG.md says what each one guarantees.
#pragma once

#define GRASSFIRE_VERSION "0.2"
#define GRASSFIRE_VERSION_MAJOR 0
#define GRASSFIRE_VERSION_MINOR 2
