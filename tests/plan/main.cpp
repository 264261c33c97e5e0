// doctest main for the "plan" suite (the GL-free planning code, no context).
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>
