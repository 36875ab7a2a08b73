#pragma once

#include <QList>
#include <QObject>
#include <QVariant>
#include <type_traits>

// Records a signal's arguments like QSignalSpy, but only in the test's own thread.
// QSignalSpy appends from whichever thread emits: for the simulation thread's signals
// that is a list written there and read here, a data race ThreadSanitizer reports. This
// spy receives the signal queued, so the records are touched by one thread only.
class QueuedSignalSpy : public QObject {
  public:
    template <typename Sender, typename... Args>
    QueuedSignalSpy(const Sender* sender, void (Sender::*signal)(Args...)) {
        connect(
            sender, signal, this,
            [this](Args... args) {
                records_.append(QVariantList{QVariant::fromValue(std::decay_t<Args>(args))...});
            },
            Qt::QueuedConnection);
    }

    qsizetype count() const { return records_.size(); }
    const QVariantList& last() const { return records_.last(); }
    QVariantList takeFirst() { return records_.takeFirst(); }

  private:
    QList<QVariantList> records_;
};
