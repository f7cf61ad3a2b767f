/**
 * @class vtkCatmullClarkAtlasFilter
 * @brief Catmull-Clark subdivision of any polygonal vtkPolyData through the
 * meshpaint patch atlas on an OpenCL device.
 *
 * Output: the level-L surface as quads (welded), or with LimitOn() its limit
 * positions and the point array "Normals". Level numbering follows
 * OpenSubdiv: level L is L Catmull-Clark steps from the input.
 */
#ifndef vtkCatmullClarkAtlasFilter_h
#define vtkCatmullClarkAtlasFilter_h

#include "meshpaintVisModule.h" // for MESHPAINTVIS_EXPORT

#include <vtkPolyDataAlgorithm.h> // for vtkPolyDataAlgorithm

#include <string> // for std::string

class MESHPAINTVIS_EXPORT vtkCatmullClarkAtlasFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkCatmullClarkAtlasFilter* New();
  vtkTypeMacro(vtkCatmullClarkAtlasFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  //@{
  /// Subdivision level, 1 or more (default 2).
  vtkSetClampMacro(Level, int, 1, 12);
  vtkGetMacro(Level, int);
  //@}

  //@{
  /// Output limit positions and normals instead of level-L points.
  vtkSetMacro(Limit, bool);
  vtkGetMacro(Limit, bool);
  vtkBooleanMacro(Limit, bool);
  //@}

  //@{
  /// OpenCL device selector ("gpu", "cpu", "P:D", part of a name); empty:
  /// MESHPAINT_DEVICE or the default device.
  vtkSetStdStringFromCharMacro(Device);
  vtkGetCharFromStdStringMacro(Device);
  //@}

  /// Message of the last failed update, empty after a good one.
  const char* GetLastError() const { return this->LastError.c_str(); }

protected:
  vtkCatmullClarkAtlasFilter();
  ~vtkCatmullClarkAtlasFilter() override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Level = 2;
  bool Limit = false;
  std::string Device;
  std::string LastError;

private:
  vtkCatmullClarkAtlasFilter(const vtkCatmullClarkAtlasFilter&) = delete;
  void operator=(const vtkCatmullClarkAtlasFilter&) = delete;
};

#endif
