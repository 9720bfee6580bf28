#include <cstdio>
int main() { std::puts("regio-solve"); return 0; }
