#pragma once
// A long QtTest suite split across processes, so that ctest can run it on both cores:
// with PAPERFOLD_TEST_SHARD="k/n" in the environment the suite runs its k-th share of
// test functions (every n-th, in declaration order, starting at the k-th). Without it,
// or when functions are named on the command line, the suite runs as QTEST_MAIN would.
// tests/CMakeLists.txt registers one ctest entry per share.
#include <QMetaMethod>
#include <QTest>

namespace pf::testing {

inline bool isTestFunction(const QMetaMethod& m) {
    if (m.methodType() != QMetaMethod::Slot || m.access() != QMetaMethod::Private ||
        m.parameterCount() != 0)
        return false;
    const QByteArray name = m.name();
    return name != "init" && name != "cleanup" && name != "initTestCase" &&
           name != "cleanupTestCase" && !name.endsWith("_data");
}

inline int execShard(QObject* suite, int argc, char** argv) {
    const QByteArray spec = qgetenv("PAPERFOLD_TEST_SHARD");
    if (spec.isEmpty() || argc > 1) return QTest::qExec(suite, argc, argv);
    const QList<QByteArray> parts = spec.split('/');
    bool kOk = false, nOk = false;
    const int k = parts.value(0).toInt(&kOk);
    const int n = parts.value(1).toInt(&nOk);
    if (parts.size() != 2 || !kOk || !nOk || n < 1 || k < 1 || k > n) {
        qCritical("PAPERFOLD_TEST_SHARD must be k/n with 1 <= k <= n, not '%s'", spec.constData());
        return 2;
    }
    QStringList args{QString::fromLocal8Bit(argv[0])};
    const QMetaObject* meta = suite->metaObject();
    int index = 0;
    for (int m = meta->methodOffset(); m < meta->methodCount(); ++m) {
        const QMetaMethod method = meta->method(m);
        if (!isTestFunction(method)) continue;
        if (index++ % n == k - 1) args << QString::fromLatin1(method.name());
    }
    if (args.size() == 1) return 0; // more shares than functions: this one has none
    return QTest::qExec(suite, args);
}

} // namespace pf::testing

// QTEST_MAIN, sharded. QTEST_MAIN_SETUP makes the application object QTEST_MAIN would.
#define PAPERFOLD_SHARDED_TEST_MAIN(TestObject)                                                    \
    int main(int argc, char* argv[]) {                                                             \
        QTEST_MAIN_SETUP()                                                                         \
        TestObject tc;                                                                             \
        QTEST_SET_MAIN_SOURCE_PATH                                                                 \
        return pf::testing::execShard(&tc, argc, argv);                                            \
    }
