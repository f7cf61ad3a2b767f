/**
 * @class vtkPaintView
 * @brief The interactive painting window: painted surfaces, their brush, their picker.
 *
 * Holds the engine's paint scene (one object or several, each with its own
 * atlas), a render window showing each object with its materials and its
 * own level of detail, a vtkSurfacePicker for brush centres, a brush cursor,
 * the on-screen settings and a help overlay. vtkPaintInteractorStyle turns mouse
 * and keys into BeginStroke()/ContinueStroke()/EndStroke() and HandleKey()
 * through a narrow interface (PaintControls.h); the view knows nothing of it.
 *
 * Its parts live in files named for them: vtkPaintViewScene.cxx (the
 * objects painted), vtkPaintViewStrokes.cxx (strokes, undo, recording),
 * SceneDrawing (what each object's actor draws, level of detail), BrushCursor
 * (picking and the brush ring), WindowKeys (key bindings and help),
 * ViewText (status line and help overlay), SceneFiles (Save and Export).
 *
 * A drag is one stroke, painted once as its path grows (the engine's
 * StrokeSession): what the user sees while drawing is the stroke a stroke
 * script applies. Every session is recorded that way:
 * GetRecording() is a stroke script that `meshpaint paint` replays to the
 * same bits (given the same meshes in the same order). *
 * Strokes go to the scene as `meshpaint paint` applies them to several
 * meshes: object, tangent and screen brushes paint every object within
 * reach, so a stroke may cross objects in contact; a parameter-space dab
 * paints the nearest object only. Undo and redo act on all objects.
 *
 * Methods that can fail return 0 and leave the reason in GetLastError().
 */
#ifndef vtkPaintView_h
#define vtkPaintView_h

#include "meshpaintVisModule.h" // for MESHPAINTVIS_EXPORT

#include <vtkObject.h> // for vtkObject

#include <memory> // for std::unique_ptr
#include <string> // for std::string
#include <vector> // for std::vector

class vtkPaintSurface;
class vtkPolyData;
class vtkRenderWindow;
class vtkRenderWindowInteractor;
class vtkRenderer;
class vtkSurfacePicker;

namespace meshpaint {
struct BaseMesh;
class BrushSettings;
struct LabelClass;
class PaintScene;
class PaintSurface;
struct Project;
struct ProjectOrigin;
struct StrokeScript;
}

class MESHPAINTVIS_EXPORT vtkPaintView : public vtkObject
{
public:
  static vtkPaintView* New();
  vtkTypeMacro(vtkPaintView, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  //@{
  /// Painting level, 1 to 12 (default 3), and OpenCL device selector (see
  /// `meshpaint devices`; empty: default). Set before the surface.
  vtkSetClampMacro(Level, int, 1, 12);
  vtkGetMacro(Level, int);
  vtkSetStdStringFromCharMacro(Device);
  vtkGetCharFromStdStringMacro(Device);
  /// "buffer", "image", or empty for the device's default.
  vtkSetStdStringFromCharMacro(Storage);
  vtkGetCharFromStdStringMacro(Storage);
  //@}

  //@{
  /// Window size and offscreen rendering (for tests and scripts); set
  /// before Initialize().
  vtkSetVector2Macro(Size, int);
  vtkGetVector2Macro(Size, int);
  vtkSetMacro(OffScreen, bool);
  vtkGetMacro(OffScreen, bool);
  vtkBooleanMacro(OffScreen, bool);
  //@}

  //@{
  /// The paper's high-quality look at rest: light from the camera diffused
  /// over the atlas in this many smoothing passes (texture-space subsurface
  /// lighting, tone-mapped); 0 (default): VTK's lighting. Key b toggles 0 and 60.
  vtkSetClampMacro(SubsurfacePasses, int, 0, 10000);
  vtkGetMacro(SubsurfacePasses, int);
  /// Level of detail: while the camera moves or a stroke is drawn, the
  /// surface is drawn with the texels of this coarser level (at the
  /// positions, normals and channels of the painting level); the painting
  /// level when the view rests. -1 (default): automatic (see LodFrameRate);
  /// 0: off; larger than Level: Level.
  vtkSetClampMacro(LodLevel, int, -1, 12);
  vtkGetMacro(LodLevel, int);
  /// The level drawn while moving now: LodLevel, or the automatic choice.
  int GetLodLevelInUse();
  /// Frames per second the automatic level of detail aims at (default 10):
  /// it draws the finest level below Level whose drawing takes at most half
  /// a frame at the time per quad measured when the view rests.
  vtkSetClampMacro(LodFrameRate, double, 0.1, 1000.0);
  vtkGetMacro(LodFrameRate, double);
  /// Smooths the edges of frames at rest with FXAA (default on); frames
  /// drawn while moving are never smoothed, to keep them fast.
  void SetAntiAliasing(bool on);
  vtkGetMacro(AntiAliasing, bool);
  vtkBooleanMacro(AntiAliasing, bool);
  /// Draws from the engine's own arrays where the device's memory is the
  /// host's (PoCL's CPU devices, integrated GPUs): kernels write the
  /// patches that change in place and nothing is copied (default on; takes
  /// effect for surfaces shown after it is set). Elsewhere, and when off,
  /// the changed vertices are read back into VTK's arrays.
  vtkSetMacro(ShareArrays, bool);
  vtkGetMacro(ShareArrays, bool);
  vtkBooleanMacro(ShareArrays, bool);
  /// Memory the undo steps of each object may take, in MiB (default 512);
  /// the oldest steps go first.
  vtkSetClampMacro(UndoBudget, double, 0.0, 1.0e9);
  vtkGetMacro(UndoBudget, double);
  /// Whether object `object` is drawn from shared arrays now.
  bool IsSharingArrays(int object = 0);
  /// Quads of the painted surface at the painting level.
  vtkIdType GetFaceCount();
  /// The level drawn now.
  int GetShownLevel();
  /// The painted surface of object `object` at the painting level, as drawn
  /// at rest (its points and arrays are the drawing's); null out of range.
  vtkPolyData* GetPaintedPolyData(int object = 0);
  /// Draws as while the camera moves (true) or as at rest (false); the
  /// interactor style does this itself during camera interaction.
  void SetMoving(bool moving);
  //@}

  /// The folder Save() and Export() write to (default "meshpaint-session").
  vtkSetStdStringFromCharMacro(SaveDirectory);
  vtkGetCharFromStdStringMacro(SaveDirectory);

  //@{
  /// The surface to paint: a mesh file (OBJ, OFF, PLY, STL) or the polygons
  /// of a vtkPolyData. Builds the atlas at Level on the device. Replaces
  /// whatever the view painted before.
  int LoadMesh(const char* path);
  int SetInputData(vtkPolyData* polygons);
  //@}

  //@{
  /// One more object for the scene, at the level of the objects already
  /// there. Its outputs are named for it: the file's name without
  /// extension, "input" for polygons ("_2", "_3", ... when taken). The brush
  /// starts afresh, sized to the whole scene.
  int AddMesh(const char* path);
  int AddInputData(vtkPolyData* polygons);
  //@}

  //@{
  /// The objects painted: how many, and the name of object k (null out of
  /// range), which names its folder under SaveDirectory.
  int GetNumberOfObjects();
  const char* GetObjectName(int k);
  /// The object under display pixel (x, y) facing the viewer, as a stroke
  /// starting there would find it; -1 where there is none.
  int PickObject(int x, int y);
  //@}
#ifndef __VTK_WRAP__
  /// The same from an engine mesh (the command line loads and reports it).
  int SetBaseMesh(const meshpaint::BaseMesh& mesh);
  int AddBaseMesh(const meshpaint::BaseMesh& mesh);
  /// Paints on a surface someone else holds too (SetPaintSurface());
  /// Level becomes the surface's. Replaces what the view painted before.
  void SetSurface(std::shared_ptr<meshpaint::PaintSurface> surface, const std::string& name = "surface");
  /// One more such surface for the scene.
  /// \throw meshpaint::InputError when its level is not the scene's
  void AddSurface(std::shared_ptr<meshpaint::PaintSurface> surface, const std::string& name);
  /// The project the first object came from: Save() then also writes
  /// surface.meshpaint into that object's folder, this project continued
  /// (its labels, scan and earlier history kept). Set after the surface.
  void SetProject(const meshpaint::Project& project);
  /// True when this view paints on `surface`.
  bool Shows(const std::shared_ptr<meshpaint::PaintSurface>& surface) const;
  /// Applies a parsed script whose pattern and stamp files are loaded.
  int ApplyScript(const meshpaint::StrokeScript& script);
#endif

  /// Paints on the surface of a vtkPaintSurface filter (updated first): its
  /// strokes, undo and history are the filter's, and Save() continues the
  /// project the filter loaded. Neither keeps the other: the engine surface
  /// is shared. Call the filter's ViewPainted() after painting here.
  /// Replaces what the view painted before; 0 when the update fails.
  int SetPaintSurface(vtkPaintSurface* filter);

  /// Applies a stroke script's strokes (recorded like any other stroke).
  int ApplyStrokes(const char* json);

  /// Draws into `window` instead of a window of the view's own, with the
  /// window's interactor (a Qt widget's: QVTKOpenGLNativeWidget); the host
  /// sizes it and runs the event loop. Set before Initialize().
  void SetRenderWindow(vtkRenderWindow* window);

  /// While locked, nothing changes the surfaces: strokes do not start (a
  /// left-drag turns the camera), and undo, redo, Save(), SaveProject(),
  /// Export(), scripts and the subsurface light are refused with a message.
  /// A host locks the view while other work reads or replaces the surfaces
  /// on another thread (the studio's exports and level changes).
  void SetLocked(bool locked);
  vtkGetMacro(Locked, bool);

  /// Milliseconds the last brush step took: the dabs of one new point of a
  /// drawn stroke, painted and the display brought up to date.
  double GetLastStepTime();

  /// Creates the window, renderer, actors and interactor (not started).
  int Initialize();
  /// Runs the interactor's event loop until the window closes.
  void Start();
  /// Renders the current state.
  void Render();

  vtkRenderWindow* GetRenderWindow();
  vtkRenderer* GetRenderer();
  vtkRenderWindowInteractor* GetInteractor();
  vtkSurfacePicker* GetPicker();

  //@{
  /// A stroke at display pixels (origin bottom left). BeginStroke returns 0
  /// when no surface faces the viewer there (the caller may turn the camera
  /// instead). The stroke ends by itself at a silhouette or off the surface;
  /// further ContinueStroke() calls then do nothing until EndStroke().
  int BeginStroke(int x, int y);
  int ContinueStroke(int x, int y);
  int EndStroke();
  bool IsPainting() const;
  //@}

  //@{
  /// Label edits at display pixels (origin bottom left). FillAt fills the
  /// connected region of the class under the pixel with the brush's class
  /// (its locked classes and only-over class respected): one stroke of the
  /// history, "tool": "fill". PickAt is the eyedropper: the class there
  /// into the brush when its tool is label, else the diffuse colour. 0 when
  /// no surface faces the viewer there.
  int FillAt(int x, int y);
  int PickAt(int x, int y);
  //@}

  /// Puts the brush cursor on the surface under pixel (x, y), or hides it.
  void MoveCursor(int x, int y);

  /// Cosine below which the surface counts as turned away (a silhouette);
  /// strokes end there. Default 0.1.
  vtkSetClampMacro(SilhouetteCosine, double, 0.0, 1.0);
  vtkGetMacro(SilhouetteCosine, double);

  /// Acts on a key (VTK key symbol, e.g. "z", "bracketleft", "F1"): brush
  /// settings, undo/redo (Ctrl+Z, Ctrl+Y), save (Ctrl+S), export (Ctrl+E),
  /// help (h, F1), eyedropper under the mouse (e), fill under the mouse (g;
  /// G: fills connect diagonally or not), camera reset (r), quit (q, Escape: ExitEvent, then the
  /// interactor's TerminateApp()). 1 when it was one.
  int HandleKey(const char* keysym, bool control, bool shift);

  int Undo();
  int Redo();

  /// Saves the session into SaveDirectory: strokes.json (the recording)
  /// and surface.vtp, each atomically; with several objects, each object's
  /// surface.vtp goes into SaveDirectory/<name>/ (as `meshpaint paint -o`
  /// writes a scene). The one place a project format plugs in.
  virtual int Save();
  /// Writes the first object's surface as a project (`*.meshpaint`,
  /// atomically): the project it came from continued, or a new one, with
  /// the view's label classes. 0 for a scene of several objects.
  int SaveProject(const char* path);

  /// Writes the textured model (model.obj, model.mtl, PNG maps) of level
  /// max(1, Level - 2) into SaveDirectory (several objects: each into
  /// SaveDirectory/<name>/).
  int Export();

  /// The session so far as a stroke script (undone strokes left out).
  const char* GetRecording();

  //@{
  /// The channel the surface is shown with: "diffuse" (default: the
  /// materials), "label" (classes in their colours, unlabelled surface in
  /// its material), "specular", "roughness", "displacement" or "mask"
  /// (through a colour map). Keys v / V cycle them. 0 for another name.
  int SetShownChannel(const char* name);
  const char* GetShownChannel();
  //@}

  //@{
  /// Label classes: the colours the label channel is shown in, and the
  /// names a project saved from this window keeps. A project opened in the
  /// window brings its own. Ids without a class show in fixed colours.
  /// AddLabelClass replaces a class of the same id; 0 for a bad id or name.
  int AddLabelClass(int id, const char* name, double r, double g, double b);
  void RemoveLabelClass(int id);
  void RemoveAllLabelClasses();
  int GetNumberOfLabelClasses();
  /// A hidden class shows as unlabelled surface (default: all visible).
  void SetLabelClassVisible(int id, bool visible);
  bool GetLabelClassVisible(int id);
  //@}
#ifndef __VTK_WRAP__
  const std::vector<meshpaint::LabelClass>& GetLabelClasses() const;
  void SetLabelClasses(const std::vector<meshpaint::LabelClass>& labels);
  /// The brush the keys change (null before a surface is loaded); after
  /// changing it, call UpdateText() to show the change.
  meshpaint::BrushSettings* GetBrush();
  /// The scene painted, for its history and undone strokes.
  meshpaint::PaintScene& GetScene();
  /// The project the first object came from, null when from a mesh.
  const meshpaint::Project* GetProject() const;
  /// The project file last loaded or saved here (what a save over it checks).
  const meshpaint::ProjectOrigin& GetProjectOrigin() const;
#endif
  /// Brings the status line up to date, and tells observers (UpdateDataEvent)
  /// that the view's state changed: strokes, undo, brush, messages.
  void UpdateText();

  /// The help overlay listing the keys.
  void SetHelpVisible(bool visible);
  bool GetHelpVisible();

  /// The status line's last message ("saved ...", "nothing to undo").
  const char* GetMessage() const { return this->Message.c_str(); }

  /// Why the last call failed; empty after a good one.
  const char* GetLastError() const { return this->LastError.c_str(); }

protected:
  vtkPaintView();
  ~vtkPaintView() override;

  int Level = 3;
  int LodLevel = -1;
  double LodFrameRate = 10;
  bool AntiAliasing = true;
  bool ShareArrays = true;
  double UndoBudget = 512;
  int SubsurfacePasses = 0;
  std::string Device;
  std::string Storage;
  int Size[2] = {1024, 768};
  bool OffScreen = false;
  std::string SaveDirectory = "meshpaint-session";
  double SilhouetteCosine = 0.1;
  bool Locked = false;
  std::string LastError;
  std::string Message;

private:
  vtkPaintView(const vtkPaintView&) = delete;
  void operator=(const vtkPaintView&) = delete;

  //! Load, input or mesh as one more object (`add`) or the only one.
  int LoadObject(const char* path, bool add);
  int InputObject(vtkPolyData* polygons, bool add);
  int MeshObject(const meshpaint::BaseMesh& mesh, bool add);
  //! Adds an object to the scene and its actor to the window (throws).
  void AddObject(std::shared_ptr<meshpaint::PaintSurface> surface, const std::string& name);
  //! Empties the scene and the window.
  void RemoveObjects();
  //! Puts object `object`'s actor into the window and the picker.
  void ShowObject(std::size_t object);

  int Step(bool back); // Undo (back) or Redo
  //! True (with the reason in LastError and the status line) while locked.
  bool RefusedWhileLocked();
  //! Result of a look-up at a pixel: on a surface facing the viewer?
  bool PickFacing(int x, int y, double point[3], double normal[3]);
  //! Puts the cursor at the surface under (x, y), or hides it; true when shown.
  bool PlaceCursor(int x, int y);
  //! Rebuilds what is drawn from the engine; `geometry`: positions changed.
  void Refresh(bool geometry);
  //! The level drawn while moving.
  int CoarseLevel();
  //! Object `object`'s painted surface at `level` (Level or CoarseLevel()),
  //! rebuilt if stale.
  vtkPolyData* Surface(std::size_t object, int level);
  //! Hands the actors the level that fits the moment.
  void Show();
  //! Hands the surface under the last pick the picked patch and (u, v).
  void HintSnap();

  struct Internals;
  std::unique_ptr<Internals> Impl;
};

#endif
