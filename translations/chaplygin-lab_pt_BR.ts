<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="pt_BR">
<context>
    <name>AnimationDialog</name>
    <message>
        <source>Rendering %1 frames…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::AccuracyReadout</name>
    <message>
        <source>Distance of the controlled knife point P from the prescribed path&apos;s own point at the same arc length: the tracking constraint residual</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Distance from the paper&apos;s closed form (line and circle presets, constant energy)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>t</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>off the path</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>vs closed form</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>energy drift</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>free energy drift</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;b&gt;Models and methods&lt;/b&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (paper %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no closed form for this scene</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>T varies by design in constant-speed mode</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::AnimationDialog</name>
    <message>
        <source>Export animation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>clip.gif, clip.mp4, or frames/ for PNG frames</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> fps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>px</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> × real time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plots beside the canvas</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>GIF and MP4 need the ffmpeg program; a folder gets PNG frames.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Frame rate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Size</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>GIF (*.gif);;MP4 video (*.mp4);;PNG frames into a folder (*)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::GalleryMenu</name>
    <message>
        <source>&amp;Gallery</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> (refused)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::MainWindow</name>
    <message>
        <source>Path</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>System and parameters</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plots</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Methods</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Accuracy</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Type a path</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change the corners</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Draw a path</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Edit the drawn path</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export &amp;plots…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ctrl+E</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export &amp;CSV…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ctrl+Shift+E</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Fit scene</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ctrl+0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>F&amp;ollow body</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ctrl+B</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zoom &amp;in</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zoom &amp;out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Animation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Methods</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compute &amp;work-precision</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ctrl+Shift+W</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Cancel work-precision</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Physics notes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Physics notes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;p&gt;The knife point P follows the prescribed path. The control angle Ψ satisfies tan Ψ = ρ/b (eq. 45); χ = Ψ − (a/b)φ is the driving angle and λ = m b dχ/dt the control multiplier. The control is workless, so the kinetic energy stays constant in the energy mode.&lt;/p&gt;&lt;p&gt;The ghost is the free (LagrangeĽ&apos;Alembert, NeimarkĿufaev) sleigh from the same initial state: it turns away and ends on a straight line.&lt;/p&gt;&lt;p&gt;Disk and carriage reduce to a sleigh with effective mass m_eff, offset a and radius of gyration b (Apps. A, B).&lt;/p&gt;&lt;p&gt;Models in use: %1&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;About Chaplygin Lab</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>About Chaplygin Lab</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;b&gt;Chaplygin Lab %1&lt;/b&gt;&lt;p&gt;Control of nonholonomic Chaplygin systems (Antunes, Sigaud, de Moraes, Braz. J. Phys. 2009): sleigh, rolling disk and two-wheeled carriage.&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Preset %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tabulating the path…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Refused: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gallery: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Chaplygin Lab</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The scene has unsaved changes. Save them?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot save &apos;%1&apos;: the scene does not solve (%2); fix it or undo first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plots written to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CSV written to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open scene</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scenes (*.json);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save scene</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scenes (*.json)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export plots (PNG, PDF and SVG) into</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export CSV</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CSV (*.csv)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>untitled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1%2 — Chaplygin Lab</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sweep</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export &amp;animation…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Wrote %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Animation export cancelled</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::MethodsPanel</name>
    <message>
        <source>Compute work-precision</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sweep every method&apos;s tolerances and step sizes for the current scene (Ctrl+Shift+W)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Error against cost per solve for every method: press Compute.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>problem</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>chosen method</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>error [m]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>s/solve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pareto</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sweeping the methods in a worker thread…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancelling after the configuration under way…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cancelled: the scene changed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The sweep failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>yes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;b&gt;References&lt;/b&gt;&lt;br&gt;controlled: %1&lt;br&gt;free: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 configurations; horizons %2 s (controlled), %3 s (free).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stopped (%1) after %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::ParametersPanel</name>
    <message>
        <source>Chaplygin sleigh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rolling disk (App. A)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Two-wheeled carriage (App. B)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The Chaplygin system; each reduces to a sleigh with m_eff, a and b</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;System</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>enter b, derive I</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>enter I, derive b</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>b² = a² + I/m: give the radius of gyration b [m] or the inertia I [kg m²]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Gyration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>What the control law uses: effective mass [kg], CM offset a [m], radius of gyration b about P [m], inertia I about the CM [kg m²]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>constant kinetic energy (v_T)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>constant speed along the path (v_s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Energy: T = m v_T²/2 fixed (sec. 4); speed: ds/dt = v_s fixed (App. C)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Mode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>v_T = √(2T/m_eff), the speed the kinetic energy is worth</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>v_s, the constant speed of P along the path</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>m_eff = %1 kg, a = %2 m, b = %3 m, I = %4 kg m²</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(no valid system)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change %1 to %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose the %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Enter I instead of b</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Enter b instead of I</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Constant energy</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Constant speed</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::PathPanel</name>
    <message>
        <source>Preset (the paper&apos;s examples)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(choose a preset)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Load one of the paper&apos;s four examples with the paper&apos;s parameters</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Typed path</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>graph y(x)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>parametric x(u), y(u)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>y as a function of x [m], e.g. -sin(x) or 0.5*x + 1; press Enter to apply</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>y(x) =</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>x as a function of u [m], e.g. 2*cos(u)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>x(u) =</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>y as a function of u [m], e.g. 2*sin(u)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>y(u) =</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The range of x [m] (graph) or of u (parametric), traversed from the first to the second</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>x from, to</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Apply path</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tabulate the typed path (Enter in a field does the same)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drawn path</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Draw on the canvas</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Press and drag on the canvas to draw a new path; it is sampled and smoothed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>smooth (spline through the points)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>pivot (straight segments, turn in place)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>How a drawn path&apos;s corners are followed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Corners</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Smooth corners: spline bandwidth in point spacings (0 passes through every point)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Smoothing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>u from, to</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Current path: %1 drawn points, %2 corners</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>pivot</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>smooth</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::PlotsPanel</name>
    <message>
        <source> — click or drag to move the animation to that time</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::SceneCanvas</name>
    <message>
        <source>Wheel or +/-: zoom; drag or arrows: pan; F: fit scene; B: follow body</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>controlled body and its trail (tracks the path)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>free motion from the same start (translucent ghost)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>path (● start, □ end), coloured by its curvature κ: red right turn, grey straight, blue left turn</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Draw mode: drag to draw a new path; drag a square to move a point, right-click it to delete it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>t = %1 s of %2 s    scale %3 px/m</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::SweepPanel</name>
    <message>
        <source>The parameter to vary; the others keep the scene&apos;s values</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run sweep</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose a parameter and a range, then Run sweep. Click a point to load its value.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>from</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>to</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>values</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plot</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sweeping %1 over %2 values…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The sweep failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 values of %2 from %3 to %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancelled after %1. Click a point to load it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1. Click a point to load it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set %1 = %2 from the sweep</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::TimelineBar</name>
    <message>
        <source>Timeline</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Step &amp;back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>One step back (,)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Play</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Play or pause (Space)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Step &amp;forward</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>One step forward (.)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Loop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start again at the end</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Playback speed: simulated seconds per real second</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scrub through time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> t = %1 s / %2 s</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>
