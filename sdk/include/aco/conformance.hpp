#pragma once
// Moved to aco/sdk/conformance.hpp. This name stays for one release (sdk/CHANGELOG.md).
#include "aco/sdk/conformance.hpp"
