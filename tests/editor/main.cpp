// editor_tests: every editor test class in one executable. The first argument
// names the class to run (REGIO_QTEST_MAIN, support/qt_test_registry.h); the
// rest go to QtTest as they would to that class's own executable. Without a
// class name it lists the classes.
#include "support/qt_test_registry.h"

#include <cstdio>
#include <vector>

int main(int argc, char* argv[])
{
    const auto& classes = regio::test::qtTestClasses();
    const auto found = argc > 1 ? classes.find(argv[1]) : classes.end();
    if (found == classes.end()) {
        if (argc > 1)
            std::fprintf(stderr, "editor_tests: no test class %s\n", argv[1]);
        std::fprintf(stderr, "usage: editor_tests CLASS [QtTest arguments]; the classes:\n");
        for (const auto& entry : classes)
            std::fprintf(stderr, "  %s\n", entry.first.c_str());
        return 2;
    }
    // The program name, then QtTest's arguments: the class name is ours.
    std::vector<char*> arguments{argv[0]};
    arguments.insert(arguments.end(), argv + 2, argv + argc);
    arguments.push_back(nullptr);
    return found->second(int(arguments.size()) - 1, arguments.data());
}
