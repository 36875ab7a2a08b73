#include "EditorDialogs.h"

#include "Subdivision.h"

#include <QColorDialog>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QLabel>
#include <QSettings>
#include <algorithm>

namespace pf {

namespace {
const QString kLastFolderKey = QStringLiteral("dialogs/lastFolder");
} // namespace

QString EditorDialogs::startingPlace(FileDialog kind, const QString& current) {
    if (kind == FileDialog::Save && !current.isEmpty()) return current;
    const QString last = QSettings().value(kLastFolderKey).toString();
    return !last.isEmpty() && QFileInfo(last).isDir() ? last : QDir::homePath();
}

QString EditorDialogs::chooseFile(QWidget* parent, FileDialog kind, const QString& current) {
    const QString sheets = tr("PaperFold sheets (*.paper)");
    const QString from = startingPlace(kind, current);
    QString chosen;
    switch (kind) {
    case FileDialog::Open:
        chosen = QFileDialog::getOpenFileName(parent, tr("Open Sheet"), from, sheets);
        break;
    case FileDialog::Save:
        chosen = QFileDialog::getSaveFileName(parent, tr("Save Sheet"), from, sheets);
        break;
    case FileDialog::ExportImage:
        chosen = QFileDialog::getSaveFileName(parent, tr("Export Image"), from,
                                              tr("PNG images (*.png)"));
        break;
    case FileDialog::ExportMesh:
        chosen = QFileDialog::getSaveFileName(parent, tr("Export Mesh"), from,
                                              tr("Meshes (*.obj *.ply *.glb)"));
        break;
    case FileDialog::PaperImage:
        chosen = QFileDialog::getOpenFileName(parent, tr("Picture for the Paper"), from,
                                              tr("Images (*.png *.jpg *.jpeg *.bmp *.webp)"));
        break;
    case FileDialog::SaveRecording:
        chosen = QFileDialog::getSaveFileName(parent, tr("Save Recording"), from,
                                              tr("PaperFold recordings (*.paperrec)"));
        break;
    }
    rememberChosen(chosen);
    return chosen;
}

void EditorDialogs::rememberChosen(const QString& chosen) {
    if (!chosen.isEmpty()) QSettings().setValue(kLastFolderKey, QFileInfo(chosen).absolutePath());
}

void EditorDialogs::showError(QWidget* parent, const QString& message) {
    QMessageBox::critical(parent, tr("PaperFold"), message);
}

QMessageBox::StandardButton EditorDialogs::askToSave(QWidget* parent) {
    return QMessageBox::warning(parent, tr("PaperFold"),
                                tr("The sheet has unsaved changes. Save them?"),
                                QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
}

QSize EditorDialogs::chooseImageSize(QWidget* parent, const QSize& offered) {
    bool ok = false;
    const QString text = QInputDialog::getText(
        parent, tr("Export Image"), tr("Size in pixels (width x height):"), QLineEdit::Normal,
        QStringLiteral("%1x%2").arg(offered.width()).arg(offered.height()), &ok);
    if (!ok) return QSize();
    const QStringList wh = text.split(QLatin1Char('x'));
    if (wh.size() != 2) return QSize(0, 0); // unreadable: the window says what it expects
    // A negative side would make an invalid QSize, which means "cancelled".
    return QSize(std::max(0, wh[0].trimmed().toInt()), std::max(0, wh[1].trimmed().toInt()));
}

QColor EditorDialogs::chooseColor(QWidget* parent, const QColor& current) {
    return QColorDialog::getColor(current, parent, tr("Paper Colour"));
}

int EditorDialogs::chooseMeshSubdivision(QWidget* parent, int current) {
    QInputDialog dialog(parent);
    dialog.setWindowTitle(tr("Export Mesh"));
    // The range is said: the box refused 9 without a word, and a user could not tell why.
    dialog.setLabelText(tr("Subdivision level, 0 to %1: 0 writes the simulation mesh; each level "
                           "splits every triangle in four along the paper's curved surface.")
                            .arg(kMaxSubdivisionLevel));
    dialog.setInputMode(QInputDialog::IntInput);
    dialog.setIntRange(0, kMaxSubdivisionLevel);
    dialog.setIntValue(current);
    // On one line the sentence made the dialog about 750 pixels wide.
    if (auto* label = dialog.findChild<QLabel*>()) {
        label->setWordWrap(true);
        label->setMinimumWidth(320);
    }
    return dialog.exec() == QDialog::Accepted ? dialog.intValue() : -1;
}

} // namespace pf
