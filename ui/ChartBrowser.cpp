#include "ChartBrowser.h"

#include <QDialog>
#include <QDir>
#include <QFileDialog>
#include <QLabel>
#include <QScrollArea>
#include <QSettings>
#include <QVBoxLayout>

namespace pf {

namespace {

const QString kSettingsKey = QStringLiteral("bench/folder");

QFileInfoList chartsIn(const QString& folder) {
    return QDir(folder).entryInfoList({QStringLiteral("bench_*.png")}, QDir::Files, QDir::Time);
}

} // namespace

ChartBrowser::ChartBrowser(QWidget* parent)
    : QObject(parent), parent_(parent),
      folder_(QSettings().value(kSettingsKey, QStringLiteral("bench")).toString()) {}

void ChartBrowser::showLatest() {
    QFileInfoList charts = chartsIn(folder_);
    if (charts.isEmpty()) {
        // The picker's title is all a user sees: it says why it opened.
        const QString picked = QFileDialog::getExistingDirectory(
            parent_,
            tr("No chart in %1 yet: choose the folder 'paperfold bench --output-dir' wrote")
                .arg(QDir::toNativeSeparators(folder_)),
            folder_);
        if (picked.isEmpty()) return;
        folder_ = picked;
        QSettings().setValue(kSettingsKey, picked);
        charts = chartsIn(picked);
    }
    if (charts.isEmpty()) {
        emit failed(tr("No bench_*.png in %1. Run: paperfold bench --output-dir %1").arg(folder_));
        return;
    }
    lastChart_ = charts.first().absoluteFilePath();
    auto* dialog = new QDialog(parent_);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setWindowTitle(charts.first().fileName());
    auto* layout = new QVBoxLayout(dialog);
    auto* picture = new QLabel(dialog);
    picture->setPixmap(QPixmap(lastChart_));
    auto* scroll = new QScrollArea(dialog);
    scroll->setWidget(picture);
    layout->addWidget(scroll);
    dialog->resize(1000, 640);
    dialog->show();
}

} // namespace pf
