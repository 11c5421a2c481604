#include <cstdio>
int main() { std::puts("vplant"); return 0; }
