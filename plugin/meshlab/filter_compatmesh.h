// MeshLab 2020.09 filter plugin: compatible triangulations of two planar
// boundaries (Surazhsky & Gotsman) and the sweep between them. The plugin
// only translates between MeshLab layers and compatmesh; the workers are
// compatible_pair and sweep.
#ifndef FILTER_COMPATMESH_H
#define FILTER_COMPATMESH_H

#include <QObject>

#include <common/interfaces.h>
#include <common/meshmodel.h>

class FilterCompatMesh : public QObject, public MeshFilterInterface
{
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(MESH_FILTER_INTERFACE_IID)
  Q_INTERFACES(MeshFilterInterface)

 public:
  enum { FP_COMPATIBLE_TRIANGULATION, FP_COMPATIBLE_SWEEP };

  FilterCompatMesh();

  QString pluginName() const override;
  QString filterName(FilterIDType filter) const override;
  QString filterInfo(FilterIDType filter) const override;
  FilterClass getClass(QAction *) override;
  FILTER_ARITY filterArity(QAction *) const override { return FIXED; }

  void initParameterSet(QAction *, MeshDocument &, RichParameterList &) override;
  bool applyFilter(QAction *, MeshDocument &, const RichParameterList &, vcg::CallBackPos *) override;

 private:
  bool fail(const QString &message);
};

#endif
