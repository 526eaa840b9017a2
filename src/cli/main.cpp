// whirl command line entry point; subcommands are registered in src/cli/.
#include <cstdio>
int main() { std::puts("whirl " WHIRL_VERSION); return 0; }
