// Exported OBJ, PLY and GLB files re-read by independent readers.
#include "Scenes.h"
#include "Simulation.h"
#include "Subdivision.h"
#include "SurfaceExport.h"

#include <QTemporaryDir>
#include <QtTest>
#include <assimp/Importer.hpp>
#include <assimp/scene.h>
#include <tiny_gltf.h>
#include <tiny_obj_loader.h>

using namespace pf;

namespace {

SurfaceMesh crumpledSurface(int level) {
    Simulation sim(*makeScene("press"));
    for (int k = 0; k < 300; ++k) sim.step();
    return subdivideSheet(sim.world().sheet, 1.0, level);
}

} // namespace

class TestExport : public QObject {
    Q_OBJECT

    QTemporaryDir dir;

  private slots:
    void formatFromExtension() {
        MeshFormat f;
        QVERIFY(meshFormatForPath(QStringLiteral("a/b.OBJ"), &f) && f == MeshFormat::Obj);
        QVERIFY(meshFormatForPath(QStringLiteral("x.ply"), &f) && f == MeshFormat::Ply);
        QVERIFY(meshFormatForPath(QStringLiteral("x.glb"), &f) && f == MeshFormat::Glb);
        QVERIFY(!meshFormatForPath(QStringLiteral("x.stl"), &f));
    }

    void objReadByTinyObjLoader() {
        const SurfaceMesh m = crumpledSurface(2);
        const QString path = dir.filePath(QStringLiteral("sheet.obj"));
        QString error;
        QVERIFY2(writeSurface(m, path, MeshFormat::Obj, true, &error), qPrintable(error));
        tinyobj::ObjReader reader;
        QVERIFY(reader.ParseFromFile(path.toStdString()));
        QCOMPARE(reader.GetAttrib().vertices.size(), 3 * m.positions.size());
        QCOMPARE(reader.GetAttrib().normals.size(), 3 * m.normals.size());
        QCOMPARE(reader.GetShapes().size(), std::size_t(1));
        QCOMPARE(reader.GetShapes()[0].mesh.num_face_vertices.size(), m.triangles.size());
        // Values survive the text format to about 1e-9 m.
        QVERIFY(std::abs(reader.GetAttrib().vertices[3 * 5 + 1] - m.positions[5].y()) < 1e-6);
    }

    void plyReadByAssimp() {
        const SurfaceMesh m = crumpledSurface(2);
        const QString path = dir.filePath(QStringLiteral("sheet.ply"));
        QString error;
        QVERIFY2(writeSurface(m, path, MeshFormat::Ply, true, &error), qPrintable(error));
        Assimp::Importer importer;
        const aiScene* scene = importer.ReadFile(path.toStdString(), 0);
        QVERIFY2(scene, importer.GetErrorString());
        QCOMPARE(scene->mNumMeshes, 1u);
        QCOMPARE(std::size_t(scene->mMeshes[0]->mNumFaces), m.triangles.size());
        QCOMPARE(std::size_t(scene->mMeshes[0]->mNumVertices), m.positions.size());
        QVERIFY(scene->mMeshes[0]->HasNormals());
    }

    void glbReadByTinyGltf() {
        const SurfaceMesh m = crumpledSurface(3);
        const QString path = dir.filePath(QStringLiteral("sheet.glb"));
        QString error;
        QVERIFY2(writeSurface(m, path, MeshFormat::Glb, true, &error), qPrintable(error));
        tinygltf::Model model;
        tinygltf::TinyGLTF loader;
        std::string err, warn;
        QVERIFY2(loader.LoadBinaryFromFile(&model, &err, &warn, path.toStdString()), err.c_str());
        QCOMPARE(model.meshes.size(), std::size_t(1));
        const auto& prim = model.meshes[0].primitives[0];
        QCOMPARE(model.accessors[prim.attributes.at("POSITION")].count, m.positions.size());
        QCOMPARE(model.accessors[prim.attributes.at("NORMAL")].count, m.positions.size());
        QCOMPARE(model.accessors[prim.indices].count, 3 * m.triangles.size());
        QVERIFY(model.materials[0].doubleSided);
    }

    void withoutNormals() {
        const SurfaceMesh m = crumpledSurface(1);
        const QString path = dir.filePath(QStringLiteral("plain.obj"));
        QVERIFY(writeSurface(m, path, MeshFormat::Obj, false, nullptr));
        tinyobj::ObjReader reader;
        QVERIFY(reader.ParseFromFile(path.toStdString()));
        QVERIFY(reader.GetAttrib().normals.empty());
        QCOMPARE(reader.GetShapes()[0].mesh.num_face_vertices.size(), m.triangles.size());
    }
};

QTEST_GUILESS_MAIN(TestExport)
#include "test_export.moc"
