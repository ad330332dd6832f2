#pragma once
// Moved to aco/sdk/testing.hpp. This name stays for one release (sdk/CHANGELOG.md).
#include "aco/sdk/testing.hpp"
