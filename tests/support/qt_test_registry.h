#pragma once
// All editor test classes live in one executable, editor_tests: linking one
// binary instead of one per class is what a build on few cores spends its
// time on. Each test file registers its class here with REGIO_QTEST_MAIN
// where a QtTest executable would say QTEST_MAIN, and editor_tests runs the
// class its first argument names (tests/editor/main.cpp):
//
//   editor_tests SceneDocumentTest [QtTest arguments]
//
// Exactly as that class's own executable would: one class per process, the
// same application object and set-up, so a class sees no state another one
// left behind. CTest runs every class as its own test.
#include <QApplication>
#include <QTest>

#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>

namespace regio::test {

// What the class's executable would have run as main().
using QtTestMain = int (*)(int argc, char** argv);

// Test classes by class name.
inline std::map<std::string, QtTestMain>& qtTestClasses()
{
    static std::map<std::string, QtTestMain> classes;
    return classes;
}

inline bool registerQtTestClass(const char* name, QtTestMain main)
{
    if (!qtTestClasses().emplace(name, main).second) {
        std::fprintf(stderr, "two editor test classes are named %s\n", name);
        std::abort();
    }
    return true;
}

} // namespace regio::test

// The body of QTEST_MAIN_WRAPPER (qtest.h) as a function of its own:
// TestObject::initMain() if it has one, the application `setup` makes, then
// the test class run with the remaining arguments.
#define REGIO_QTEST_REGISTER(TestObject, setup)                                                                        \
    namespace {                                                                                                        \
    int regioQtTestMain##TestObject(int argc, char** argv)                                                             \
    {                                                                                                                  \
        QT_PREPEND_NAMESPACE(QTest::Internal::callInitMain)<TestObject>();                                             \
        setup TestObject tc;                                                                                           \
        QTEST_SET_MAIN_SOURCE_PATH                                                                                     \
        return QTest::qExec(&tc, argc, argv);                                                                          \
    }                                                                                                                  \
    const bool regioQtTestRegistered##TestObject =                                                                     \
        ::regio::test::registerQtTestClass(#TestObject, regioQtTestMain##TestObject);                                  \
    }

// Instead of QTEST_MAIN(TestObject): a QApplication set up as QTEST_MAIN sets it up.
#define REGIO_QTEST_MAIN(TestObject) REGIO_QTEST_REGISTER(TestObject, QTEST_MAIN_SETUP())

// Instead of QTEST_GUILESS_MAIN(TestObject): a QCoreApplication, no GUI.
#define REGIO_QTEST_GUILESS_MAIN(TestObject) REGIO_QTEST_REGISTER(TestObject, QTEST_QAPP_SETUP(QCoreApplication))

// For a class that needs its own main (e.g. a default surface format set
// before the application exists): `mainFunction` is that main under another
// name, int(int argc, char** argv).
#define REGIO_QTEST_OWN_MAIN(TestObject, mainFunction)                                                                 \
    namespace {                                                                                                        \
    const bool regioQtTestRegistered##TestObject = ::regio::test::registerQtTestClass(#TestObject, mainFunction);      \
    }
