<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN">
<context>
    <name>AcknowledgeDataLoss</name>
    <message>
        <location filename="../widgets/commands/acknowledge_data_loss_command.cpp" line="+20"/>
        <source>Acknowledge data loss</source>
        <translation>确认数据丢失</translation>
    </message>
</context>
<context>
    <name>CleaningStep</name>
    <message>
        <location filename="../widgets/panels/cleaning_step.cpp" line="+33"/>
        <source> on 1 marker</source>
        <translation>，涉及 1 个标记点</translation>
    </message>
    <message>
        <location line="+1"/>
        <source> on %1 markers</source>
        <translation>，涉及 %1 个标记点</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>1 sample changed</source>
        <translation>已更改 1 个采样点</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 samples changed</source>
        <translation>已更改 %1 个采样点</translation>
    </message>
</context>
<context>
    <name>FillRuleText</name>
    <message>
        <location filename="../widgets/models/fill_rule_text.cpp" line="+12"/>
        <source>%1 s</source>
        <translation>%1 秒</translation>
    </message>
    <message numerus="yes">
        <location line="+9"/>
        <source>over the %n-frame limit</source>
        <translation>
            <numerusform>超过 %n 帧的上限</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>over the %1 limit</source>
        <translation>超过 %1 的上限</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>at the take&apos;s start: no extrapolation</source>
        <translation>位于拍摄数据开头：不外推</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>at the take&apos;s end: no extrapolation</source>
        <translation>位于拍摄数据末尾：不外推</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>marker seen in %1 % of the take</source>
        <translation>标记点在 %1 % 的拍摄数据中可见</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>marker never seen</source>
        <translation>标记点从未出现</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a model output, not a marker</source>
        <translation>模型输出，不是标记点</translation>
    </message>
</context>
<context>
    <name>GapFillStep</name>
    <message>
        <location filename="../widgets/panels/gap_fill_step.cpp" line="+35"/>
        <source>No gap filled</source>
        <translation>未填补任何缺口</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>1 gap filled</source>
        <translation>已填补 1 个缺口</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 gaps filled</source>
        <translation>已填补 %1 个缺口</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>, 1 sample</source>
        <translation>，1 个采样点</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>, %1 samples</source>
        <translation>，%1 个采样点</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1 longer than %2</source>
        <translation>%1 个长于 %2</translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>%n edge gap(s)</source>
        <translation>
            <numerusform>%n 个边缘缺口</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>%n on rarely seen markers</source>
        <translation>
            <numerusform>%n 个位于很少出现的标记点上</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>%n on markers never seen</source>
        <translation>
            <numerusform>%n 个位于从未出现的标记点上</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>%n the method could not fill</source>
        <translation>
            <numerusform>%n 个方法无法填补</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>%n on model outputs</source>
        <translation>
            <numerusform>%n 个在模型输出上</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>; %n left open</source>
        <translation>
            <numerusform>；%n 个未填补</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>HeadStabilizationStep</name>
    <message>
        <location filename="../widgets/panels/head_stabilization_step.cpp" line="+65"/>
        <source>No reference markers: choose them in Marker ▸ Reference Markers…</source>
        <translation>没有参考标记点：请在“标记点 ▸ 参考标记点…”中选择</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>head pose measured in %1 of %2 frames</source>
        <translation>在 %2 帧中的 %1 帧测得头部姿态</translation>
    </message>
</context>
<context>
    <name>LiveLinkRecordingImport</name>
    <message>
        <location filename="../widgets/actions/live_link_recording_import.cpp" line="+29"/>
        <source>Load a rig first: the recording&apos;s curves animate its shapes.</source>
        <translation>请先加载绑定模型：录制的曲线驱动其形状。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1: a recording needs two rows or more with increasing timecodes.</source>
        <translation>%1：录制需要两行或更多且时间码递增。</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Open Live Link Recording %1</source>
        <translation>打开 Live Link 录制 %1</translation>
    </message>
</context>
<context>
    <name>MarkerMenus</name>
    <message>
        <location filename="../widgets/actions/marker_menus.cpp" line="+24"/>
        <source>&amp;Marker</source>
        <translation>标记点(&amp;M)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Delete Markers</source>
        <translation>删除标记点(&amp;D)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Remove the selected markers from the take (undoable)</source>
        <translation>从拍摄中移除所选标记点（可撤销）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Add &amp;Averaged Marker…</source>
        <translation>添加平均标记点(&amp;A)…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A virtual marker at the mean of the selected markers</source>
        <translation>位于所选标记点平均位置的虚拟标记点</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Swap Over Range</source>
        <translation>在范围内交换(&amp;S)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Exchange the data of the two selected markers over the selected frame range</source>
        <translation>在所选帧范围内交换两个所选标记点的数据</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Reference Markers…</source>
        <translation>参考标记点(&amp;R)…</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The head-mounted markers that head stabilization, layout planning and the face mesh use</source>
        <translation>头部稳定、布局规划和面部网格所使用的头戴标记点</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Set Selected as Reference &amp;Markers</source>
        <translation>将所选设为参考标记点(&amp;M)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Make the selected markers (at least three) the take&apos;s reference markers (undoable)</source>
        <translation>将所选标记点（至少三个）设为动捕片段的参考标记点（可撤销）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Hide Selected</source>
        <translation>隐藏所选(&amp;H)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Show &amp;All</source>
        <translation>全部显示(&amp;A)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&amp;Label</source>
        <translation>标注(&amp;L)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Track and Label</source>
        <translation>跟踪并标注(&amp;T)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Re-track the unlabelled points and give them the labels of the take&apos;s labelled markers</source>
        <translation>重新跟踪未标注的点，并赋予它们拍摄中已标注标记点的名称</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fix &amp;Swaps…</source>
        <translation>修复交换(&amp;S)…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Find frames where two labels exchange and repair the ones you accept</source>
        <translation>查找两个名称互换的帧，并修复您接受的那些</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Assign Label by Clicking</source>
        <translation>点击分配名称(&amp;A)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Select a marker in the table, then click a point in the 3D view to give it that label</source>
        <translation>在表格中选择一个标记点，然后在三维视图中点击一个点以赋予它该名称</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Labelling: select a marker in the table, then click the point that is it</source>
        <translation>标注：在表格中选择一个标记点，然后点击对应的点</translation>
    </message>
</context>
<context>
    <name>OffscreenRenderWindow</name>
    <message>
        <location filename="../widgets/views/offscreen_render_window.cpp" line="+66"/>
        <source>there is no X display (DISPLAY is not set); run under xvfb-run</source>
        <translation>没有 X 显示（未设置 DISPLAY）；请在 xvfb-run 下运行</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>cannot connect to the X display %1</source>
        <translation>无法连接到 X 显示 %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>OpenGL 3.2 is not available on this display</source>
        <translation>此显示器上没有 OpenGL 3.2</translation>
    </message>
</context>
<context>
    <name>QProgressDialog</name>
    <message>
        <location filename="../widgets/dialogs/job_dialog.cpp" line="+35"/>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
</context>
<context>
    <name>RebindMarkerCommand</name>
    <message>
        <location filename="../widgets/commands/rebind_marker_command.cpp" line="+14"/>
        <source>Unbind %1</source>
        <translation>解除 %1 的绑定</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Bind %1 to vertex %2</source>
        <translation>将 %1 绑定到顶点 %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Bind %1 to the surface</source>
        <translation>将 %1 绑定到表面</translation>
    </message>
</context>
<context>
    <name>RecoveryOffer</name>
    <message>
        <location filename="../widgets/actions/recovery_offer.cpp" line="+42"/>
        <source>an untitled take</source>
        <translation>未命名拍摄</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Recover unsaved edits?</source>
        <translation>恢复未保存的编辑？</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mocap Studio did not close normally. Unsaved edits of %1 were kept at %2. Recover them?</source>
        <translation>Mocap Studio 未正常关闭。%1 的未保存编辑已于 %2 保留。是否恢复？</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Cannot recover</source>
        <translation>无法恢复</translation>
    </message>
</context>
<context>
    <name>RemoveMarkersCommand</name>
    <message>
        <location filename="../widgets/commands/remove_markers_command.cpp" line="+19"/>
        <source>Delete marker %1</source>
        <translation>删除标记点 %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Delete %1 markers</source>
        <translation>删除 %1 个标记点</translation>
    </message>
</context>
<context>
    <name>RenameMarkerCommand</name>
    <message>
        <location filename="../widgets/commands/rename_marker_command.cpp" line="+12"/>
        <source>Rename %1 to %2</source>
        <translation>将 %1 重命名为 %2</translation>
    </message>
</context>
<context>
    <name>ReviewExport</name>
    <message>
        <location filename="../widgets/dialogs/review_export.cpp" line="+142"/>
        <source>No video at this frame</source>
        <translation>此帧没有视频</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>There is no take to review.</source>
        <translation>没有可审阅的录制。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The frames to review are outside the take.</source>
        <translation>要审阅的帧超出了录制范围。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The 3D view cannot render here: %1</source>
        <translation>3D 视图无法在此渲染：%1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The 3D view did not render frame %1.</source>
        <translation>3D 视图未能渲染第 %1 帧。</translation>
    </message>
</context>
<context>
    <name>SampleState</name>
    <message>
        <location filename="../widgets/views/sample_colors.cpp" line="+45"/>
        <source>smoothed</source>
        <translation>已平滑</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>stabilized</source>
        <translation>已稳定</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>measured</source>
        <translation>实测</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>filled</source>
        <translation>已填补</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>edited</source>
        <translation>已编辑</translation>
    </message>
</context>
<context>
    <name>SmoothingStep</name>
    <message>
        <location filename="../widgets/panels/smoothing_step.cpp" line="+135"/>
        <source>%1 smoothing</source>
        <translation>%1 平滑</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>: moves samples by RMS %1 %3, at most %2 %3 (%4, frame %5)</source>
        <translation>：采样点移动量 RMS %1 %3，最大 %2 %3（%4，第 %5 帧）</translation>
    </message>
</context>
<context>
    <name>SpikeStep</name>
    <message numerus="yes">
        <location filename="../widgets/panels/spike_step.cpp" line="+122"/>
        <source>%n bad point(s) found</source>
        <translation>
            <numerusform>发现 %n 个坏点</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>; %n beside samples just repaired: a glitch longer than a few frames is found a part at a time (its worst samples first). Repair these too, or turn on &quot;Look again until nothing new&quot; to flag whole glitches at once</source>
        <translation>
            <numerusform>；其中 %n 个紧邻刚修复的采样点：持续超过几帧的毛刺会被分段发现（最严重的采样点优先）。请一并修复这些点，或开启“反复检测直到无新发现”以一次标记整个毛刺</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>TakeUnitsMenu</name>
    <message>
        <location filename="../widgets/actions/take_units_menu.cpp" line="+30"/>
        <source>Positions Are In %1 (were read as %2)</source>
        <translation>位置单位为 %1（读取时为 %2）</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Positions Are &amp;In</source>
        <translation>位置单位(&amp;I)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The file&apos;s numbers are in this unit (nothing is rescaled; undoable)</source>
        <translation>文件中的数值使用此单位（不做换算；可撤销）</translation>
    </message>
</context>
<context>
    <name>ViewOptionActions</name>
    <message>
        <location filename="../widgets/actions/view_option_actions.cpp" line="+28"/>
        <source>Y Axis Up</source>
        <translation>Y 轴朝上</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Z Axis Up</source>
        <translation>Z 轴朝上</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>&amp;Reset Camera</source>
        <translation>重置相机(&amp;C)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Trails</source>
        <translation>轨迹(&amp;T)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Marker &amp;Links</source>
        <translation>标记点连线(&amp;L)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Show &amp;Model Outputs</source>
        <translation>显示模型输出(&amp;M)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Draw and gap-list the joint angles, forces, moments, powers and virtual points a C3D file stores as points (they are never cleaned)</source>
        <translation>绘制 C3D 文件以点形式存储的关节角度、力、力矩、功率和虚拟点，并列入缺口列表（它们从不被清理）</translation>
    </message>
    <message>
        <source>Draw and gap-list the joint angles, forces, moments and powers a C3D file stores as points (they are never cleaned)</source>
        <translation type="vanished">绘制并在缺口列表中显示 C3D 文件以点存储的关节角度、力、力矩和功率（它们从不被清理）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Follow Head</source>
        <translation>跟随头部(&amp;F)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Keep the camera on the head as it moves (the centroid of the head markers)</source>
        <translation>头部移动时相机始终对准头部（头部标记点的质心）</translation>
    </message>
</context>
<context>
    <name>mocap::studio::MainWindow</name>
    <message>
        <location filename="../app/studio/main_window.cpp" line="+104"/>
        <source>Timeline</source>
        <translation>时间轴</translation>
    </message>
    <message>
        <source>Frame %1 of %2–%3 — %4 markers selected</source>
        <translation type="vanished">第 %1 帧（%2–%3）— 已选择 %4 个标记点</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>Autosave failed: %1</source>
        <translation>自动保存失败：%1</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Markers</source>
        <translation>标记点</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Curves</source>
        <translation>曲线</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>History</source>
        <translation>历史记录</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Cleaning</source>
        <translation>清理</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Layout planning</source>
        <translation>布局规划</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Gaps</source>
        <translation>缺口</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Face Mesh</source>
        <translation>面部网格</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Blendshape Solve</source>
        <translation>混合形状求解</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Reference Video</source>
        <translation>参考视频</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Live Stream</source>
        <translation>实时流</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Weights</source>
        <translation>权重</translation>
    </message>
    <message>
        <source>Export Animation</source>
        <translation type="vanished">导出动画</translation>
    </message>
    <message>
        <source>The face mesh cannot be exported: %1</source>
        <translation type="vanished">无法导出面部网格：%1</translation>
    </message>
    <message>
        <source>Rendering the review video…</source>
        <translation type="vanished">正在渲染审阅视频…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation type="vanished">取消</translation>
    </message>
    <message>
        <source>Review video cancelled; nothing was written.</source>
        <translation type="vanished">审阅视频已取消；未写入任何内容。</translation>
    </message>
    <message>
        <source>Export Review Video</source>
        <translation type="vanished">导出审阅视频</translation>
    </message>
    <message>
        <source>The review video was not written: %1</source>
        <translation type="vanished">审阅视频未写入：%1</translation>
    </message>
    <message>
        <source>This system has no MP4 encoder, so the video was written as Motion JPEG AVI: %1</source>
        <translation type="vanished">此系统没有 MP4 编码器，因此视频以 Motion JPEG AVI 写入：%1</translation>
    </message>
    <message>
        <source>Wrote %1 (%2 frames, %3)</source>
        <translation type="vanished">已写入 %1（%2 帧，%3）</translation>
    </message>
    <message>
        <location line="+63"/>
        <source>&amp;File</source>
        <translation>文件(&amp;F)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Open…</source>
        <translation>打开(&amp;O)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open &amp;Recent</source>
        <translation>最近打开(&amp;R)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Keep Face Rig for the Next Take</source>
        <translation>为下一个拍摄保留面部绑定(&amp;K)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Opening another take keeps the face mesh, its marker binding and the blendshape rig (the actor&apos;s), bound to the markers the new take has; off, every take starts without them</source>
        <translation>打开另一个拍摄时保留面部网格、其标记点绑定和混合形状绑定（演员的），并绑定到新拍摄中已有的标记点；关闭时，每个拍摄都从空白开始</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Face rig kept for this take: %1</source>
        <translation>已为此拍摄保留面部绑定：%1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Save</source>
        <translation>保存(&amp;S)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save &amp;As…</source>
        <translation>另存为(&amp;A)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Export…</source>
        <translation>导出(&amp;E)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export Ani&amp;mation…</source>
        <translation>导出动画(&amp;M)…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export Re&amp;view Video…</source>
        <translation>导出审阅视频(&amp;V)…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export Ri&amp;g…</source>
        <translation>导出绑定模型(&amp;G)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The solved rig as FBX or glTF, or its curves as CSV, through a retarget map (Blendshape Solve)</source>
        <translation>将求解的绑定模型导出为 FBX 或 glTF，或将其曲线导出为 CSV，可经重定向映射（混合形状求解）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save &amp;Cleaning Preset…</source>
        <translation>保存清理预设(&amp;C)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Load Cleaning Preset…</source>
        <translation>加载清理预设(&amp;L)…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Quit</source>
        <translation>退出(&amp;Q)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Edit</source>
        <translation>编辑(&amp;E)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Undo</source>
        <translation>撤销(&amp;U)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Redo</source>
        <translation>重做(&amp;R)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Delete Range</source>
        <translation>删除范围(&amp;D)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Make the selected frame range of the selected markers a gap (Shift-drag on the curves)</source>
        <translation>将所选标记点的所选帧范围设为缺口（在曲线上按住 Shift 拖动）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Rename Marker…</source>
        <translation>重命名标记点(&amp;M)…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Preferences…</source>
        <translation>首选项(&amp;P)…</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>&amp;View</source>
        <translation>视图(&amp;V)</translation>
    </message>
    <message>
        <location line="+61"/>
        <source>%1 (%2)[*] — Mocap Studio</source>
        <translation>%1（%2）[*] — Mocap Studio</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Recovered unsaved edits of %1; not restored: %2</source>
        <translation>已恢复 %1 未保存的编辑；未恢复：%2</translation>
    </message>
    <message>
        <source>&amp;Reset Camera</source>
        <translation type="vanished">重置相机(&amp;C)</translation>
    </message>
    <message>
        <source>Y Axis Up</source>
        <translation type="vanished">Y 轴朝上</translation>
    </message>
    <message>
        <source>Z Axis Up</source>
        <translation type="vanished">Z 轴朝上</translation>
    </message>
    <message>
        <source>&amp;Trails</source>
        <translation type="vanished">轨迹(&amp;T)</translation>
    </message>
    <message>
        <source>Marker &amp;Links</source>
        <translation type="vanished">标记点连线(&amp;L)</translation>
    </message>
    <message>
        <source>Show &amp;Model Outputs</source>
        <translation type="vanished">显示模型输出(&amp;M)</translation>
    </message>
    <message>
        <source>Draw and gap-list the joint angles, forces, moments and powers a C3D file stores as points (they are never cleaned)</source>
        <translation type="vanished">绘制并在缺口列表中显示 C3D 文件以点存储的关节角度、力、力矩和功率（它们从不被清理）</translation>
    </message>
    <message>
        <source>&amp;Follow Head</source>
        <translation type="vanished">跟随头部(&amp;F)</translation>
    </message>
    <message>
        <source>Keep the camera on the head as it moves (the centroid of the head markers)</source>
        <translation type="vanished">头部移动时相机始终对准头部（头部标记点的质心）</translation>
    </message>
    <message>
        <location line="-82"/>
        <source>&amp;Language</source>
        <translation>语言(&amp;L)</translation>
    </message>
    <message>
        <source>Language</source>
        <translation type="vanished">语言</translation>
    </message>
    <message>
        <source>The new language is used from the next start.</source>
        <translation type="vanished">新语言将在下次启动时生效。</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>&amp;Help</source>
        <translation>帮助(&amp;H)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Manual</source>
        <translation>手册(&amp;M)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;About Mocap Studio</source>
        <translation>关于 Mocap Studio(&amp;A)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>About Mocap Studio</source>
        <translation>关于 Mocap Studio</translation>
    </message>
    <message>
        <source>3D view in the lab frame</source>
        <translation type="vanished">三维视图使用实验室坐标系</translation>
    </message>
    <message>
        <source>Head-Stabilized View</source>
        <translation type="vanished">头部稳定视图</translation>
    </message>
    <message>
        <source>&amp;Head-Stabilized View</source>
        <translation type="vanished">头部稳定视图(&amp;H)</translation>
    </message>
    <message>
        <source>Show the markers in the head frame of the reference markers (a view setting; the take is not changed)</source>
        <translation type="vanished">在参考标记点的头部坐标系中显示标记点（仅为视图设置，不会更改动捕片段）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&lt;b&gt;Mocap Studio %1&lt;/b&gt;&lt;p&gt;Cleaning and using facial optical motion capture.&lt;/p&gt;</source>
        <translation>&lt;b&gt;Mocap Studio %1&lt;/b&gt;&lt;p&gt;清理和使用面部光学动作捕捉数据。&lt;/p&gt;</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&lt;p&gt;Keys: Space play/pause, ←/→ step (Shift: 10), Home/End, PgUp/PgDn previous/next gap, Ctrl+PgUp/PgDn previous/next bad point, Ctrl+R reset camera, L marker links, H hide, Shift+H show all, Ctrl+drag rubber-band selection, Ctrl+B head-stabilized view, F camera follows the head, Ctrl+Shift+S save as.&lt;/p&gt;</source>
        <translation>&lt;p&gt;按键：空格 播放/暂停，←/→ 单帧（Shift：10 帧），Home/End，PgUp/PgDn 上一个/下一个缺口，Ctrl+PgUp/PgDn 上一个/下一个坏点，Ctrl+R 重置相机，L 标记点连线，H 隐藏，Shift+H 全部显示，Ctrl+拖动 框选，Ctrl+B 头部稳定视图，F 相机跟随头部，Ctrl+Shift+S 另存为。&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Choose at least three reference markers first (Marker ▸ Reference Markers…).</source>
        <translation type="vanished">请先选择至少三个参考标记点（标记点 ▸ 参考标记点…）。</translation>
    </message>
    <message>
        <source>3D view stabilized on the reference markers (Ctrl+B again for the lab frame)</source>
        <translation type="vanished">三维视图已按参考标记点稳定（再按 Ctrl+B 返回实验室坐标系）</translation>
    </message>
    <message>
        <source>3D view back in the lab frame: the reference markers cannot carry a head pose</source>
        <translation type="vanished">三维视图已返回实验室坐标系：参考标记点无法确定头部姿态</translation>
    </message>
    <message>
        <source>Head markers set; Edit ▸ Undo takes them back</source>
        <translation type="vanished">已设置头部标记点；编辑 ▸ 撤销可取消</translation>
    </message>
    <message>
        <source>Reference markers unchanged</source>
        <translation type="vanished">参考标记点未更改</translation>
    </message>
    <message>
        <source>Select at least three head-mounted markers first</source>
        <translation type="vanished">请先选择至少三个头戴标记点</translation>
    </message>
    <message>
        <source>The selected markers already are the reference markers</source>
        <translation type="vanished">所选标记点已经是参考标记点</translation>
    </message>
    <message>
        <source>&amp;Marker</source>
        <translation type="vanished">标记点(&amp;M)</translation>
    </message>
    <message>
        <source>&amp;Delete Markers</source>
        <translation type="vanished">删除标记点(&amp;D)</translation>
    </message>
    <message>
        <source>Remove the selected markers from the take (undoable)</source>
        <translation type="vanished">从拍摄中移除所选标记点（可撤销）</translation>
    </message>
    <message>
        <source>Add &amp;Averaged Marker…</source>
        <translation type="vanished">添加平均标记点(&amp;A)…</translation>
    </message>
    <message>
        <source>A virtual marker at the mean of the selected markers</source>
        <translation type="vanished">位于所选标记点平均位置的虚拟标记点</translation>
    </message>
    <message>
        <source>&amp;Swap Over Range</source>
        <translation type="vanished">在范围内交换(&amp;S)</translation>
    </message>
    <message>
        <source>Exchange the data of the two selected markers over the selected frame range</source>
        <translation type="vanished">在所选帧范围内交换两个所选标记点的数据</translation>
    </message>
    <message>
        <source>&amp;Reference Markers…</source>
        <translation type="vanished">参考标记点(&amp;R)…</translation>
    </message>
    <message>
        <source>The head-mounted markers that head stabilization, layout planning and the face mesh use</source>
        <translation type="vanished">头部稳定、布局规划和面部网格所使用的头戴标记点</translation>
    </message>
    <message>
        <source>Set Selected as Reference &amp;Markers</source>
        <translation type="vanished">将所选设为参考标记点(&amp;M)</translation>
    </message>
    <message>
        <source>Make the selected markers (at least three) the take&apos;s reference markers (undoable)</source>
        <translation type="vanished">将所选标记点（至少三个）设为动捕片段的参考标记点（可撤销）</translation>
    </message>
    <message>
        <source>&amp;Hide Selected</source>
        <translation type="vanished">隐藏所选(&amp;H)</translation>
    </message>
    <message>
        <source>Show &amp;All</source>
        <translation type="vanished">全部显示(&amp;A)</translation>
    </message>
    <message>
        <source>&amp;Label</source>
        <translation type="vanished">标注(&amp;L)</translation>
    </message>
    <message>
        <source>&amp;Track and Label</source>
        <translation type="vanished">跟踪并标注(&amp;T)</translation>
    </message>
    <message>
        <source>Re-track the unlabelled points and give them the labels of the take&apos;s labelled markers</source>
        <translation type="vanished">重新跟踪未标注的点，并赋予它们拍摄中已标注标记点的名称</translation>
    </message>
    <message>
        <source>Fix &amp;Swaps…</source>
        <translation type="vanished">修复交换(&amp;S)…</translation>
    </message>
    <message>
        <source>Find frames where two labels exchange and repair the ones you accept</source>
        <translation type="vanished">查找两个名称互换的帧，并修复您接受的那些</translation>
    </message>
    <message>
        <source>&amp;Assign Label by Clicking</source>
        <translation type="vanished">点击分配名称(&amp;A)</translation>
    </message>
    <message>
        <source>Select a marker in the table, then click a point in the 3D view to give it that label</source>
        <translation type="vanished">在表格中选择一个标记点，然后在三维视图中点击一个点以赋予它该名称</translation>
    </message>
    <message>
        <source>Labelling: select a marker in the table, then click the point that is it</source>
        <translation type="vanished">标注：在表格中选择一个标记点，然后点击对应的点</translation>
    </message>
    <message>
        <source>Opening %1…</source>
        <translation type="vanished">正在打开 %1…</translation>
    </message>
    <message>
        <source>Cancelled</source>
        <translation type="vanished">已取消</translation>
    </message>
    <message>
        <source>Cannot open file</source>
        <translation type="vanished">无法打开文件</translation>
    </message>
    <message numerus="yes">
        <source>⚠ Incomplete: %n warning(s)</source>
        <translation type="vanished">
            <numerusform>⚠ 不完整：%n 条警告</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>⚠ %n warning(s)</source>
        <translation type="vanished">
            <numerusform>⚠ %n 条警告</numerusform>
        </translation>
    </message>
    <message>
        <source>Show every warning from reading the file</source>
        <translation type="vanished">显示读取文件时的所有警告</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation type="vanished">已保存 %1</translation>
    </message>
    <message>
        <source>%1 — note: %2</source>
        <translation type="vanished">%1 — 注意：%2</translation>
    </message>
    <message>
        <source>Save Cleaning Preset</source>
        <translation type="vanished">保存清理预设</translation>
    </message>
    <message>
        <source>Cleaning presets (*.json)</source>
        <translation type="vanished">清理预设 (*.json)</translation>
    </message>
    <message>
        <source>Include this take&apos;s head markers (%1)</source>
        <translation type="vanished">包含此录制的头部标记点（%1）</translation>
    </message>
    <message>
        <source>none chosen</source>
        <translation type="vanished">未选择</translation>
    </message>
    <message>
        <source>A preset carries cleaning options; head markers belong to a take. Include them only when every take the preset is for names its head markers the same way: a take without them then fails with that reason.</source>
        <translation type="vanished">预设保存清理选项；头部标记点属于某个录制。仅当预设适用的每个录制都以相同方式命名其头部标记点时才包含它们：没有这些标记点的录制将因此失败。</translation>
    </message>
    <message>
        <source>The preset was not saved: %1</source>
        <translation type="vanished">预设未保存：%1</translation>
    </message>
    <message>
        <source>Saved the cleaning preset %1</source>
        <translation type="vanished">已保存清理预设 %1</translation>
    </message>
    <message>
        <source>Loaded the cleaning preset %1 into the Cleaning panel; nothing changes the take until Apply</source>
        <translation type="vanished">已将清理预设 %1 加载到清理面板；点击应用之前录制不会改变</translation>
    </message>
    <message>
        <source>; it turns off %1 (left as they were)</source>
        <translation type="vanished">；它关闭了 %1（保持原样）</translation>
    </message>
    <message>
        <source>; its head markers (%1) are not this take&apos;s: the take keeps its own</source>
        <translation type="vanished">；其头部标记点（%1）不属于此录制：录制保留自己的</translation>
    </message>
    <message>
        <source>Load Cleaning Preset</source>
        <translation type="vanished">加载清理预设</translation>
    </message>
    <message>
        <source>Cleaning presets (*.json);;All files (*)</source>
        <translation type="vanished">清理预设 (*.json);;所有文件 (*)</translation>
    </message>
    <message>
        <source>The preset was not loaded: %1</source>
        <translation type="vanished">预设未加载：%1</translation>
    </message>
    <message>
        <source>The face mesh of the recovered session could not be restored: %1</source>
        <translation type="vanished">无法还原所恢复会话的面部网格：%1</translation>
    </message>
    <message>
        <location line="+81"/>
        <source>Cancel the running job before closing</source>
        <translation>请先取消正在运行的任务再关闭</translation>
    </message>
    <message>
        <source>Open take</source>
        <translation type="vanished">打开动捕片段</translation>
    </message>
    <message>
        <source>Overwrite the original?</source>
        <translation type="vanished">覆盖原始文件？</translation>
    </message>
    <message>
        <source>Save over %1? The original capture is replaced by the edited take.</source>
        <translation type="vanished">要覆盖 %1 吗？原始捕捉数据将被编辑后的动捕片段替换。</translation>
    </message>
    <message>
        <source>Cannot save</source>
        <translation type="vanished">无法保存</translation>
    </message>
    <message>
        <source>Save take as</source>
        <translation type="vanished">动捕片段另存为</translation>
    </message>
    <message>
        <source>C3D (*.c3d);;TRC (*.trc)</source>
        <translation type="vanished">C3D (*.c3d);;TRC (*.trc)</translation>
    </message>
    <message>
        <source>Export</source>
        <translation type="vanished">导出</translation>
    </message>
    <message>
        <source>C3D (*.c3d);;TRC (*.trc);;CSV (*.csv);;BVH (*.bvh);;FBX markers (*.fbx)</source>
        <translation type="vanished">C3D (*.c3d);;TRC (*.trc);;CSV (*.csv);;BVH (*.bvh);;FBX 标记点 (*.fbx)</translation>
    </message>
    <message>
        <source>Cannot export</source>
        <translation type="vanished">无法导出</translation>
    </message>
    <message>
        <source>Exported %1</source>
        <translation type="vanished">已导出 %1</translation>
    </message>
    <message>
        <source>Unsaved edits</source>
        <translation type="vanished">未保存的修改</translation>
    </message>
    <message>
        <source>The take has unsaved edits. Save them?</source>
        <translation type="vanished">动捕片段有未保存的修改。是否保存？</translation>
    </message>
    <message>
        <location line="-44"/>
        <source>Untitled</source>
        <translation>未命名</translation>
    </message>
    <message>
        <source>%1 (incomplete)[*] — Mocap Studio</source>
        <translation type="vanished">%1（不完整）[*] — Mocap Studio</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1[*] — Mocap Studio</source>
        <translation>%1[*] — Mocap Studio</translation>
    </message>
    <message>
        <source>an untitled take</source>
        <translation type="vanished">未命名拍摄</translation>
    </message>
    <message>
        <source>Recover unsaved edits?</source>
        <translation type="vanished">恢复未保存的编辑？</translation>
    </message>
    <message>
        <source>Mocap Studio did not close normally. Unsaved edits of %1 were kept at %2. Recover them?</source>
        <translation type="vanished">Mocap Studio 未正常关闭。%1 的未保存编辑已于 %2 保留。是否恢复？</translation>
    </message>
    <message>
        <source>Cannot recover</source>
        <translation type="vanished">无法恢复</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Recovered unsaved edits of %1; save them to keep them</source>
        <translation>已恢复 %1 的未保存编辑；请保存以保留它们</translation>
    </message>
    <message>
        <source>Motion capture (*.c3d *.trc);;All files (*)</source>
        <translation type="vanished">动作捕捉文件 (*.c3d *.trc);;所有文件 (*)</translation>
    </message>
</context>
<context>
    <name>mocap::ui::ActorActions</name>
    <message>
        <location filename="../widgets/actions/actor_actions.cpp" line="+57"/>
        <source>&amp;Actor</source>
        <translation>演员(&amp;A)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;New from Neutral Frame…</source>
        <translation>从中性帧新建(&amp;N)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The bound markers at the current frame as an actor&apos;s neutral (mocap actor --neutral TAKE:FRAME)</source>
        <translation>当前帧的已绑定标记点作为演员的中性姿态（mocap actor --neutral TAKE:FRAME）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Calibrate from ROM Take…</source>
        <translation>从 ROM 拍摄校准(&amp;C)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Each shape&apos;s extent for the loaded actor from a range-of-motion take (mocap actor --rom)</source>
        <translation>从动作范围拍摄得到已加载演员每个形状的幅度（mocap actor --rom）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Load Actor…</source>
        <translation>加载演员(&amp;L)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>An actor profile for the solve (mocap solve --actor)</source>
        <translation>用于求解的演员配置（mocap solve --actor）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>C&amp;lear Actor</source>
        <translation>清除演员(&amp;L)</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Open a take, load a rig and bind the markers to its neutral first.</source>
        <translation>请先打开拍摄、加载绑定模型并将标记点绑定到其中性网格。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>No actor made: %1</source>
        <translation>未创建演员：%1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Load a rig and an actor (or make one from a neutral frame) first.</source>
        <translation>请先加载绑定模型和演员（或从中性帧新建一个）。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Calibrating from %1…</source>
        <translation>正在从 %1 校准…</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Calibration cancelled; the actor is as it was.</source>
        <translation>校准已取消；演员保持不变。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Not calibrated: %1</source>
        <translation>未校准：%1</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Cannot load the actor: %1</source>
        <translation>无法加载演员：%1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Actor %1: the solve uses its neutral and range.</source>
        <translation>演员 %1：求解使用其中性姿态和幅度。</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>New Actor from Neutral Frame</source>
        <translation>从中性帧新建演员</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+13"/>
        <source>Actor profiles (*.json)</source>
        <translation>演员配置 (*.json)</translation>
    </message>
    <message>
        <location line="-5"/>
        <source>Range-of-Motion Take</source>
        <translation>动作范围拍摄</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Takes (*.c3d *.trc);;All files (*)</source>
        <translation>拍摄 (*.c3d *.trc);;所有文件 (*)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Save the Calibrated Actor</source>
        <translation>保存已校准的演员</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Load Actor</source>
        <translation>加载演员</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Actor profiles (*.json);;All files (*)</source>
        <translation>演员配置 (*.json);;所有文件 (*)</translation>
    </message>
</context>
<context>
    <name>mocap::ui::Autosave</name>
    <message>
        <location filename="../widgets/document/autosave.cpp" line="+117"/>
        <source>Cannot create the recovery folder %1</source>
        <translation>无法创建恢复文件夹 %1</translation>
    </message>
</context>
<context>
    <name>mocap::ui::BlendshapeSolvePanel</name>
    <message>
        <location filename="../widgets/panels/blendshape_solve_panel.cpp" line="+134"/>
        <source>The take has changed since this solve; Solve again to update the weights.</source>
        <translation>自此次求解后拍摄已更改；请重新求解以更新权重。</translation>
    </message>
    <message>
        <location line="+21"/>
        <location line="+277"/>
        <source>Load a rig, bind the markers to its neutral in the Face Mesh panel, then Solve.</source>
        <translation>加载绑定模型，在面部网格面板中将标记点绑定到其中性形状，然后求解。</translation>
    </message>
    <message>
        <location line="-272"/>
        <source>Rig</source>
        <translation>绑定模型</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+260"/>
        <source>No rig</source>
        <translation>无绑定模型</translation>
    </message>
    <message>
        <location line="-256"/>
        <source>Load glTF Rig…</source>
        <translation>加载 glTF 绑定模型…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A .glb or .gltf with the neutral mesh and one morph target per shape</source>
        <translation>包含中性网格且每个形状一个变形目标的 .glb 或 .gltf 文件</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Load OBJ Rig…</source>
        <translation>加载 OBJ 绑定模型…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A neutral OBJ/PLY and a folder with one OBJ per shape, named after it</source>
        <translation>一个中性 OBJ/PLY 和一个文件夹，每个形状一个以其命名的 OBJ</translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+33"/>
        <source>Solve</source>
        <translation>求解</translation>
    </message>
    <message>
        <location line="-29"/>
        <source>Temporal (smooth over time)</source>
        <translation>时间平滑</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ridge (per frame)</source>
        <translation>岭回归（逐帧）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bounded least squares (per frame)</source>
        <translation>有界最小二乘（逐帧）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Method:</source>
        <translation>方法：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Automatic (GCV)</source>
        <translation>自动（GCV）</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Ridge weight λ, relative to the shapes&apos; mean squared motion</source>
        <translation>岭权重 λ，相对于形状的均方运动</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>λ:</source>
        <translation>λ：</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Weight of the weights&apos; second differences over time, as at 100 Hz</source>
        <translation>权重随时间的二阶差分的权重（按 100 Hz）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Smoothness:</source>
        <translation>平滑度：</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>L1 weight pulling unused shapes to zero</source>
        <translation>将未使用的形状拉向零的 L1 权重</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sparsity:</source>
        <translation>稀疏度：</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Solve every frame of the take to the rig&apos;s weights (on a worker; Cancel stops it)</source>
        <translation>将拍摄的每一帧求解为绑定模型的权重（在后台运行；取消可停止）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Cancelling…</source>
        <translation>正在取消…</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Shapes</source>
        <translation>形状</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Filter shapes (e.g. mouth)</source>
        <translation>筛选形状（例如 mouth）</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Selected shapes are drawn in the Weights view and edited below</source>
        <translation>选中的形状在权重视图中绘制，并在下方编辑</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Scale</source>
        <translation>缩放</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Zero</source>
        <translation>清零</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Scale by:</source>
        <translation>缩放倍数：</translation>
    </message>
    <message>
        <location line="+5"/>
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Smooth</source>
        <translation>平滑</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Low-pass:</source>
        <translation>低通：</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Edits apply to the selected shapes over the frame range selected on the curves (Shift-drag), or the whole take; Ctrl+Z undoes them.</source>
        <translation>编辑作用于选中的形状，范围为曲线上选中的帧范围（Shift 拖动）或整个拍摄；Ctrl+Z 可撤销。</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Display and export</source>
        <translation>显示与导出</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Show the solved rig in the 3D view</source>
        <translation>在 3D 视图中显示求解后的绑定模型</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Beside the markers (else over them)</source>
        <translation>在标记点旁边（否则与其重叠）</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Open Live Link Recording…</source>
        <translation>打开 Live Link 录制…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A Live Link Face CSV as the rig&apos;s weight curves, through a map (undoable)</source>
        <translation>将 Live Link Face CSV 通过映射作为绑定模型的权重曲线（可撤销）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export Weights…</source>
        <translation>导出权重…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Weight curves as CSV: one column per shape (plain or Live Link Face layout)</source>
        <translation>权重曲线导出为 CSV：每个形状一列（普通或 Live Link Face 布局）</translation>
    </message>
    <message>
        <location line="+341"/>
        <source>Solve the take, or open a Live Link recording, first: there are no curves to export.</source>
        <translation>请先求解拍摄或打开 Live Link 录制：没有可导出的曲线。</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Cannot open the recording: %1</source>
        <translation>无法打开录制：%1</translation>
    </message>
    <message numerus="yes">
        <location line="+4"/>
        <source>Opened %1: %n sample(s) at %2 Hz from %3 as the curves of %4 shapes; exports keep its rate and timecode.</source>
        <translation>
            <numerusform>已打开 %1：%n 个采样，%2 Hz，起于 %3，作为 %4 个形状的曲线；导出保留其帧率和时间码。</numerusform>
        </translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Recorded at %1 Hz: resampled to the take&apos;s rate.</source>
        <translation>以 %1 Hz 录制：已重采样到该录制的帧率。</translation>
    </message>
    <message>
        <source>Export Rig GLB…</source>
        <translation type="vanished">导出绑定模型 GLB…</translation>
    </message>
    <message>
        <source>The rig with its morph targets and the weights as an animation (Blender, Unity, three.js)</source>
        <translation type="vanished">带变形目标的绑定模型，权重作为动画（Blender、Unity、three.js）</translation>
    </message>
    <message>
        <location line="-274"/>
        <source>Wait for the running job, or cancel it.</source>
        <translation>请等待正在运行的任务，或将其取消。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Reading %1…</source>
        <translation>正在读取 %1…</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Cannot read the rig %1: %2</source>
        <translation>无法读取绑定模型 %1：%2</translation>
    </message>
    <message numerus="yes">
        <location line="+14"/>
        <source>%1: %n shape(s), %2 vertices</source>
        <translation>
            <numerusform>%1：%n 个形状，%2 个顶点</numerusform>
        </translation>
    </message>
    <message>
        <location line="-8"/>
        <source>Rig loaded. Bind the markers to its neutral in the Face Mesh panel (Auto-Bind or Load Binding), then Solve.</source>
        <translation>绑定模型已加载。请在面部网格面板中将标记点绑定到其中性形状（自动绑定或加载绑定），然后求解。</translation>
    </message>
    <message>
        <location line="-112"/>
        <source>Export Rig…</source>
        <translation>导出绑定模型…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The rig with its blend shapes and the weights as animation curves, FBX or glTF (Unreal, Maya, MotionBuilder, Blender, Unity), through a retarget map, keys reduced</source>
        <translation>带混合形状的绑定模型及作为动画曲线的权重，FBX 或 glTF（Unreal、Maya、MotionBuilder、Blender、Unity），可经重定向映射并精简关键帧</translation>
    </message>
    <message>
        <location line="+112"/>
        <source>Rig loaded. Solve when ready.</source>
        <translation>绑定模型已加载。准备好后即可求解。</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Rig kept from the previous take: %1. Solve when ready.</source>
        <translation>已保留上一个拍摄的绑定：%1。准备好后求解。</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>A job is already running.</source>
        <translation>已有任务在运行。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Open a take first.</source>
        <translation>请先打开一个拍摄。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Load a rig first.</source>
        <translation>请先加载绑定模型。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The Face Mesh panel shows another mesh than this rig&apos;s neutral; load the rig again.</source>
        <translation>面部网格面板显示的网格不是此绑定模型的中性形状；请重新加载绑定模型。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Bind the markers to the rig&apos;s neutral in the Face Mesh panel first (Auto-Bind or Load Binding).</source>
        <translation>请先在面部网格面板中将标记点绑定到绑定模型的中性形状（自动绑定或加载绑定）。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Solving…</source>
        <translation>正在求解…</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Solve failed: %1</source>
        <translation>求解失败：%1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Cancelled; the weights are as they were.</source>
        <translation>已取消；权重保持不变。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cancelled</source>
        <translation>已取消</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Solved %1 frames from %2 markers (%3, λ %4%5) in %6 s; marker residual %7 mm mean, %8 mm max.</source>
        <translation>已从 %2 个标记点求解 %1 帧（%3，λ %4%5），用时 %6 秒；标记点残差平均 %7 毫米，最大 %8 毫米。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source> by GCV</source>
        <translation>（GCV）</translation>
    </message>
    <message numerus="yes">
        <location line="+5"/>
        <source>Warning: %n frame(s) had too few markers and hold the previous frame&apos;s weights (shaded red in the Weights view).</source>
        <translation>
            <numerusform>警告：%n 帧的标记点太少，沿用上一帧的权重（在权重视图中以红色阴影显示）。</numerusform>
        </translation>
    </message>
    <message>
        <location line="+20"/>
        <source>  (peak %1)</source>
        <translation>  （峰值 %1）</translation>
    </message>
    <message>
        <location line="+90"/>
        <source>Solve the take first.</source>
        <translation>请先求解拍摄。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Cannot write the weights: %1</source>
        <translation>无法写入权重：%1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Wrote %1</source>
        <translation>已写入 %1</translation>
    </message>
    <message>
        <source>Cannot write the rig: %1</source>
        <translation type="vanished">无法写入绑定模型：%1</translation>
    </message>
    <message>
        <location line="+66"/>
        <source>Load glTF rig</source>
        <translation>加载 glTF 绑定模型</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>glTF rigs (*.glb *.gltf);;All files (*)</source>
        <translation>glTF 绑定模型 (*.glb *.gltf);;所有文件 (*)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Load the rig&apos;s neutral mesh</source>
        <translation>加载绑定模型的中性网格</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Meshes (*.obj *.ply);;All files (*)</source>
        <translation>网格 (*.obj *.ply);;所有文件 (*)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The folder with one OBJ per shape</source>
        <translation>每个形状一个 OBJ 的文件夹</translation>
    </message>
    <message>
        <source>Weight curves (*.csv)</source>
        <translation type="vanished">权重曲线 (*.csv)</translation>
    </message>
    <message>
        <source>Live Link Face CSV (*.csv)</source>
        <translation type="vanished">Live Link Face CSV (*.csv)</translation>
    </message>
    <message>
        <source>Export weights</source>
        <translation type="vanished">导出权重</translation>
    </message>
    <message>
        <source>Export animated rig</source>
        <translation type="vanished">导出动画绑定模型</translation>
    </message>
    <message>
        <source>glTF binary (*.glb)</source>
        <translation type="vanished">glTF 二进制 (*.glb)</translation>
    </message>
</context>
<context>
    <name>mocap::ui::CleaningPanel</name>
    <message>
        <location filename="../widgets/panels/cleaning_panel.cpp" line="+110"/>
        <source>Live preview</source>
        <translation>实时预览</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Selected markers only</source>
        <translation>仅限所选标记点</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Selected frame range only</source>
        <translation>仅所选帧范围</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Change only the frames selected on the curves (Shift+drag)</source>
        <translation>仅更改在曲线上选中的帧（Shift+拖动）</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Apply</source>
        <translation>应用</translation>
    </message>
    <message>
        <location line="+122"/>
        <source>Computing…</source>
        <translation>正在计算…</translation>
    </message>
    <message numerus="yes">
        <location line="+31"/>
        <source>%1 — %n sample(s) would change</source>
        <translation>
            <numerusform>%1 — 将更改 %n 个采样点</numerusform>
        </translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Next pass: %1</source>
        <translation>下一遍：%1</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Cancelled</source>
        <translation>已取消</translation>
    </message>
    <message>
        <location line="+70"/>
        <source>Nothing to apply</source>
        <translation>没有可应用的更改</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Applied: %1</source>
        <translation>已应用：%1</translation>
    </message>
</context>
<context>
    <name>mocap::ui::CleaningPresetActions</name>
    <message>
        <location filename="../widgets/actions/cleaning_preset_actions.cpp" line="+52"/>
        <location line="+22"/>
        <source>Save Cleaning Preset</source>
        <translation>保存清理预设</translation>
    </message>
    <message>
        <location line="-21"/>
        <source>Cleaning presets (*.json)</source>
        <translation>清理预设 (*.json)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Include this take&apos;s head markers (%1)</source>
        <translation>包含此录制的头部标记点（%1）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>none chosen</source>
        <translation>未选择</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>A preset carries cleaning options; head markers belong to a take. Include them only when every take the preset is for names its head markers the same way: a take without them then fails with that reason.</source>
        <translation>预设保存清理选项；头部标记点属于某个录制。仅当预设适用的每个录制都以相同方式命名其头部标记点时才包含它们：没有这些标记点的录制将因此失败。</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>The preset was not saved: %1</source>
        <translation>预设未保存：%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Saved the cleaning preset %1</source>
        <translation>已保存清理预设 %1</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Loaded the cleaning preset %1 into the Cleaning panel; nothing changes the take until Apply</source>
        <translation>已将清理预设 %1 加载到清理面板；点击应用之前录制不会改变</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>; it turns off %1 (left as they were)</source>
        <translation>；它关闭了 %1（保持原样）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>; its head markers (%1) are not this take&apos;s: the take keeps its own</source>
        <translation>；其头部标记点（%1）不属于此录制：录制保留自己的</translation>
    </message>
    <message>
        <location line="+7"/>
        <location line="+6"/>
        <source>Load Cleaning Preset</source>
        <translation>加载清理预设</translation>
    </message>
    <message>
        <location line="-4"/>
        <source>Cleaning presets (*.json);;All files (*)</source>
        <translation>清理预设 (*.json);;所有文件 (*)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The preset was not loaded: %1</source>
        <translation>预设未加载：%1</translation>
    </message>
</context>
<context>
    <name>mocap::ui::CurveView</name>
    <message>
        <location filename="../widgets/views/curve_view.cpp" line="+143"/>
        <source>Select a marker to see its curves</source>
        <translation>选择一个标记点以查看其曲线</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation type="vanished">%1 s</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>preview</source>
        <translation>预览</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>filled</source>
        <translation>已填补</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>smoothed</source>
        <translation>已平滑</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>edited</source>
        <translation>已编辑</translation>
    </message>
    <message>
        <source>+%1 more</source>
        <translation type="vanished">另有 %1 个</translation>
    </message>
    <message>
        <location line="+315"/>
        <source>%1 · frame %2 (%3 s) · %4 %5 %6</source>
        <translation>%1 · 第 %2 帧（%3 s）· %4 %5 %6</translation>
    </message>
    <message>
        <location line="+17"/>
        <source> → preview %1</source>
        <translation> → 预览 %1</translation>
    </message>
    <message>
        <location line="+100"/>
        <source>Move %1 %2 at frame %3</source>
        <translation>移动 %1 的 %2（第 %3 帧）</translation>
    </message>
</context>
<context>
    <name>mocap::ui::ExportDialog</name>
    <message>
        <location filename="../widgets/actions/animation_export.cpp" line="+19"/>
        <location filename="../widgets/dialogs/export_dialog.cpp" line="+90"/>
        <source>Export Animation</source>
        <translation>导出动画</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The face mesh cannot be exported: %1</source>
        <translation>无法导出面部网格：%1</translation>
    </message>
    <message>
        <location filename="../widgets/dialogs/export_dialog.cpp" line="+14"/>
        <source>BVH of the markers (.bvh)</source>
        <translation>标记点的 BVH（.bvh）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>FBX of the markers as animated nulls (.fbx)</source>
        <translation>标记点的 FBX，作为动画空对象 (.fbx)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>OBJ sequence of the deformed mesh (folder)</source>
        <translation>变形网格的 OBJ 序列（文件夹）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>OBJ + PC2 point cache of the deformed mesh (.pc2)</source>
        <translation>变形网格的 OBJ + PC2 点缓存（.pc2）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Format:</source>
        <translation>格式(&amp;F)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>FB&amp;X:</source>
        <translation>FBX(&amp;X):</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The units of the markers&apos; positions in the file (as mocap convert --units): Maya and MotionBuilder work in centimetres, Blender, Unreal and Unity read the declared units</source>
        <translation>文件中标记点位置的单位（同 mocap convert --units）：Maya 和 MotionBuilder 使用厘米，Blender、Unreal 和 Unity 读取声明的单位</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Units:</source>
        <translation>单位(&amp;U)：</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&amp;Browse…</source>
        <translation>浏览(&amp;B)…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Output:</source>
        <translation>输出(&amp;O)：</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>R&amp;ange:</source>
        <translation>范围(&amp;A)：</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>to</source>
        <translation>至</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>F&amp;rames:</source>
        <translation>帧(&amp;R)：</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>&amp;Export</source>
        <translation>导出(&amp;E)</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+412"/>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <location line="-391"/>
        <source>Z up</source>
        <translation>Z 向上</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Y up</source>
        <translation>Y 向上</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The take&apos;s up axis, declared in the file so the importer turns the scene upright</source>
        <translation>拍摄的向上轴，写入文件以便导入程序将场景摆正</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Keep the fewest keys within</source>
        <translation>保留最少关键帧，误差不超过</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Each marker keeps the fewest keys whose linear interpolation stays within this distance of every frame (as mocap convert --reduce); otherwise every frame is a key</source>
        <translation>每个标记点保留最少的关键帧，使其线性插值与每一帧的距离不超过此值（同 mocap convert --reduce）；否则每帧都是关键帧</translation>
    </message>
    <message>
        <location line="+6"/>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>As the take (%1)</source>
        <translation>与录制相同（%1）</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Whole take (%1–%2)</source>
        <translation>整个拍摄数据（%1–%2）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Selected range (%1–%2)</source>
        <translation>所选范围（%1–%2）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Custom</source>
        <translation>自定义</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Load a face mesh first: these formats export the deformed mesh.</source>
        <translation>请先加载面部网格：这些格式导出的是变形后的网格。</translation>
    </message>
    <message numerus="yes">
        <location line="+112"/>
        <source>Replace %n existing file(s)?</source>
        <translation>
            <numerusform>要替换 %n 个现有文件吗？</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>… and %n more</source>
        <translation>
            <numerusform>… 以及另外 %n 个</numerusform>
        </translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Replace Files?</source>
        <translation>替换文件？</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Folder for the OBJ sequence</source>
        <translation>OBJ 序列的文件夹</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export BVH</source>
        <translation>导出 BVH</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>BVH (*.bvh)</source>
        <translation>BVH (*.bvh)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export FBX</source>
        <translation>导出 FBX</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>FBX (*.fbx)</source>
        <translation>FBX (*.fbx)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export Point Cache</source>
        <translation>导出点缓存</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>PC2 point cache (*.pc2)</source>
        <translation>PC2 点缓存 (*.pc2)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Open a take first.</source>
        <translation>请先打开拍摄数据。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Choose where to export.</source>
        <translation>请选择导出位置。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Load a face mesh first: this format exports the deformed mesh.</source>
        <translation>请先加载面部网格：此格式导出的是变形后的网格。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The first frame (%1) is after the last (%2).</source>
        <translation>起始帧（%1）位于结束帧（%2）之后。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The folder %1 does not exist.</source>
        <translation>文件夹 %1 不存在。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 is a folder; choose a file name.</source>
        <translation>%1 是文件夹，请选择文件名。</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>Not exported: the existing files are kept.</source>
        <translation>未导出：已保留现有文件。</translation>
    </message>
    <message numerus="yes">
        <location line="+16"/>
        <source>Exporting %n frame(s)…</source>
        <translation>
            <numerusform>正在导出 %n 帧…</numerusform>
        </translation>
    </message>
    <message>
        <location line="+86"/>
        <source>Kept %1 of %2 keys (%3 %), largest error %4 mm (tolerance %5 mm).</source>
        <translation>保留了 %2 个关键帧中的 %1 个（%3 %），最大误差 %4 mm（容差 %5 mm）。</translation>
    </message>
    <message>
        <location line="-485"/>
        <source>Cancelling…</source>
        <translation>正在取消…</translation>
    </message>
    <message numerus="yes">
        <location line="+444"/>
        <source>Exported %n frame(s) to %1.</source>
        <translation>
            <numerusform>已将 %n 帧导出到 %1。</numerusform>
        </translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Note: %1.</source>
        <translation>注意：%1。</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Export cancelled; nothing was written.</source>
        <translation>导出已取消，未写入任何内容。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Export failed: %1</source>
        <translation>导出失败：%1</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Close</source>
        <translation>关闭</translation>
    </message>
</context>
<context>
    <name>mocap::ui::FaceMeshModel</name>
    <message numerus="yes">
        <location filename="../widgets/document/face_mesh_model.cpp" line="+118"/>
        <source>%n marker(s) bound</source>
        <translation>
            <numerusform>已绑定 %n 个标记点</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%1 of %n rig marker(s) found in this take</source>
        <translation>
            <numerusform>在此拍摄中找到 %n 个绑定标记点中的 %1 个</numerusform>
        </translation>
    </message>
    <message>
        <location line="+38"/>
        <source>Load a mesh first.</source>
        <translation>请先加载网格。</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>Head stabilization: %1</source>
        <translation>头部稳定：%1</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>No marker is bound to the mesh: auto-bind, load a binding or pick vertices.</source>
        <translation>没有标记点绑定到网格：请自动绑定、加载绑定或拾取顶点。</translation>
    </message>
</context>
<context>
    <name>mocap::ui::FaceMeshPanel</name>
    <message>
        <location filename="../widgets/panels/face_mesh_panel.cpp" line="+102"/>
        <source>Mesh and binding</source>
        <translation>网格与绑定</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+227"/>
        <source>No mesh</source>
        <translation>无网格</translation>
    </message>
    <message>
        <location line="-223"/>
        <source>Load Mesh…</source>
        <translation>加载网格…</translation>
    </message>
    <message>
        <source>A face mesh as OBJ or PLY</source>
        <translation type="vanished">OBJ 或 PLY 格式的面部网格</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A face mesh as OBJ or PLY, or a glTF rig&apos;s neutral</source>
        <translation>OBJ 或 PLY 格式的面部网格，或 glTF 绑定模型的中性形状</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Load Binding…</source>
        <translation>加载绑定…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save Binding…</source>
        <translation>保存绑定…</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Auto-Bind</source>
        <translation>自动绑定</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Align the neutral frame to the mesh and bind each marker to its nearest surface point (the selected markers when three or more are selected)</source>
        <translation>将中性帧对齐到网格，并将每个标记点绑定到离它最近的表面点（选中三个或更多标记点时仅处理所选标记点）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Pick Vertex</source>
        <translation>拾取顶点</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Select a marker, then click the mesh vertex it sits on</source>
        <translation>选择一个标记点，然后点击它所在的网格顶点</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+276"/>
        <source>Select a marker, then click its vertex on the mesh</source>
        <translation>选择一个标记点，然后在网格上点击其对应的顶点</translation>
    </message>
    <message>
        <location line="-273"/>
        <source>Undo</source>
        <translation>撤销</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Redo</source>
        <translation>重做</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Deformation</source>
        <translation>变形</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Head motion is removed with these markers before binding and deforming; they are not bound.</source>
        <translation>在绑定和变形之前用这些标记点去除头部运动；它们本身不参与绑定。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Reference markers:</source>
        <translation>参考标记点：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The frame whose marker positions are the rest mesh</source>
        <translation>以该帧的标记点位置作为静止网格</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Neutral frame:</source>
        <translation>中性帧：</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+327"/>
        <source>RBF</source>
        <translation>RBF</translation>
    </message>
    <message>
        <location line="-326"/>
        <location line="+326"/>
        <source>Laplacian</source>
        <translation>拉普拉斯</translation>
    </message>
    <message>
        <location line="-325"/>
        <source>Method:</source>
        <translation>方法：</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Kernel:</source>
        <translation>核函数：</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Kernel radius c, in mesh units</source>
        <translation>核函数半径 c，以网格单位计</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Radius:</source>
        <translation>半径：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Top, middle and bottom regions</source>
        <translation>上、中、下区域</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Weights:</source>
        <translation>权重：</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Constraint weight:</source>
        <translation>约束权重：</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Rotation-aware iterations per frame (0: linear)</source>
        <translation>每帧的旋转感知迭代次数（0：线性）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rotations:</source>
        <translation>旋转迭代：</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Compare RBF and Laplacian side by side</source>
        <translation>并排比较 RBF 与拉普拉斯</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Display</source>
        <translation>显示</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Edges</source>
        <translation>边线</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Opacity:</source>
        <translation>不透明度：</translation>
    </message>
    <message>
        <location line="+84"/>
        <source>first complete</source>
        <translation>第一个完整帧</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Cannot read the mesh %1: %2</source>
        <translation>无法读取网格 %1：%2</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Mesh</source>
        <translation>网格</translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%1: %n vertices</source>
        <translation>
            <numerusform>%1：%n 个顶点</numerusform>
        </translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Load the mesh the binding is for first.</source>
        <translation>请先加载该绑定所对应的网格。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Cannot read the binding %1: %2</source>
        <translation>无法读取绑定 %1：%2</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Cannot save the binding: %1</source>
        <translation>无法保存绑定：%1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Saved %1</source>
        <translation>已保存 %1</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Auto-bind: %1</source>
        <translation>自动绑定：%1</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Click the vertex for %1</source>
        <translation>请点击 %1 对应的顶点</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>%1 bound to vertex %2</source>
        <translation>%1 已绑定到顶点 %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>; residual %1 mm (was %2 mm)</source>
        <translation>；残差 %1 mm（原为 %2 mm）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>; residual %1 mm</source>
        <translation>；残差 %1 mm</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>Deform per frame: %1 %2 ms</source>
        <translation>每帧变形：%1 %2 ms</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>, %1 %2 ms</source>
        <translation>，%1 %2 ms</translation>
    </message>
    <message numerus="yes">
        <source>%n marker(s) bound</source>
        <translation type="vanished">
            <numerusform>已绑定 %n 个标记点</numerusform>
        </translation>
    </message>
    <message>
        <location line="+16"/>
        <source>; mean residual %1 mm</source>
        <translation>；平均残差 %1 mm</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Neutral frame %1; set-up %2 ms</source>
        <translation>中性帧 %1；预处理 %2 ms</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Load face mesh</source>
        <translation>加载面部网格</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Meshes (*.obj *.ply *.glb *.gltf);;All files (*)</source>
        <translation>网格 (*.obj *.ply *.glb *.gltf);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Meshes (*.obj *.ply);;All files (*)</source>
        <translation type="vanished">网格 (*.obj *.ply);;所有文件 (*)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Load marker binding</source>
        <translation>加载标记点绑定</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Bindings (*.json);;All files (*)</source>
        <translation>绑定 (*.json);;所有文件 (*)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Save marker binding</source>
        <translation>保存标记点绑定</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Bindings (*.json)</source>
        <translation>绑定 (*.json)</translation>
    </message>
</context>
<context>
    <name>mocap::ui::FrameStatusLabel</name>
    <message>
        <location filename="../widgets/views/frame_status_label.cpp" line="+21"/>
        <source>Frame %1 of %2–%3 — %4 markers selected</source>
        <translation>第 %1 帧（%2–%3）— 已选择 %4 个标记点</translation>
    </message>
</context>
<context>
    <name>mocap::ui::FrameStripView</name>
    <message>
        <location filename="../widgets/views/frame_strip_view.cpp" line="+132"/>
        <source>%1 s</source>
        <translation>%1 秒</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>+%1 more</source>
        <translation>另有 %1 个</translation>
    </message>
</context>
<context>
    <name>mocap::ui::GapFillStep</name>
    <message>
        <location filename="../widgets/panels/gap_fill_step.cpp" line="+19"/>
        <source>Method</source>
        <translation>方法</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Neighbours</source>
        <translation>邻近点数</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+5"/>
        <source>unlimited</source>
        <translation>不限</translation>
    </message>
    <message>
        <location line="-4"/>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <location line="+5"/>
        <source> frames</source>
        <translation> 帧</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Longer gaps are left open: filling them would invent motion</source>
        <translation>更长的缺口保持未填补：填补它们会凭空捏造运动</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Longest gap</source>
        <translation>最长缺口</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>= frames</source>
        <translation>= 帧</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Extrapolate edge gaps</source>
        <translation>外推边缘缺口</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fill before a marker&apos;s first and after its last valid sample (invents motion nobody measured; off by default)</source>
        <translation>在标记点的第一个有效采样点之前和最后一个有效采样点之后进行填补（会捏造无人测量过的运动；默认关闭）</translation>
    </message>
    <message>
        <location line="+8"/>
        <source> % of the take</source>
        <translation> %（占拍摄数据）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>fill every marker</source>
        <translation>填补所有标记点</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Markers seen in fewer frames are left open, unless they are selected and &quot;Selected markers only&quot; is on</source>
        <translation>可见帧数少于此值的标记点不予填补，除非它们已被选中且“仅限所选标记点”已开启</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Skip markers seen under</source>
        <translation>跳过可见比例低于此值的标记点</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Gaps left open and why; click one to go there</source>
        <translation>未填补的缺口及原因；点击某项可跳转到该处</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Left open</source>
        <translation>未填补</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Gaps</source>
        <translation>缺口</translation>
    </message>
    <message>
        <location line="+81"/>
        <source>%1, frames %2–%3 (%4)</source>
        <translation>%1，第 %2–%3 帧（%4）</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>; %1 left open: </source>
        <translation>；%1 个未填补：</translation>
    </message>
</context>
<context>
    <name>mocap::ui::GapListPanel</name>
    <message>
        <location filename="../widgets/panels/gap_list_panel.cpp" line="+132"/>
        <source>Filter markers…</source>
        <translation>筛选标记点…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Only open gaps</source>
        <translation>仅未填补的缺口</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>Check Shown</source>
        <translation>勾选显示项</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Check every open gap the filter shows</source>
        <translation>勾选筛选结果中所有未填补的缺口</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Uncheck All</source>
        <translation>全部取消勾选</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Live preview</source>
        <translation>实时预览</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Show the fill of the checked (or selected) gaps over the views before filling</source>
        <translation>在填补之前，于各视图中显示已勾选（或已选中）缺口的填补结果</translation>
    </message>
    <message>
        <location line="+13"/>
        <location line="+144"/>
        <source>Fill</source>
        <translation>填补</translation>
    </message>
    <message>
        <location line="-99"/>
        <source>Show Gap</source>
        <translation>显示缺口</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fill This Gap</source>
        <translation>填补此缺口</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Allow Filling This Gap</source>
        <translation>允许填补此缺口</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>Check gaps, or select rows, to preview their fill; double-click a gap to go to it.</source>
        <translation>勾选缺口或选中行以预览其填补结果；双击缺口可跳转到该处。</translation>
    </message>
    <message>
        <location line="+52"/>
        <source>Fill 1 Checked Gap</source>
        <translation>填补 1 个已勾选的缺口</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Fill %1 Checked Gaps</source>
        <translation>填补 %1 个已勾选的缺口</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Fill Selected Gap</source>
        <translation>填补所选缺口</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Fill %1 Selected Gaps</source>
        <translation>填补 %1 个所选缺口</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fill the checked gaps, or else the selected ones, each with its method (Ctrl+Return)</source>
        <translation>填补已勾选的缺口（若无则填补所选缺口），各自使用其方法（Ctrl+Return）</translation>
    </message>
    <message>
        <location line="+57"/>
        <source>No open gap to fill</source>
        <translation>没有可填补的缺口</translation>
    </message>
    <message numerus="yes">
        <location line="+20"/>
        <source>Computing the fill of %n gap(s)…</source>
        <translation>
            <numerusform>正在计算 %n 个缺口的填补…</numerusform>
        </translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Cancelled</source>
        <translation>已取消</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>1 gap filled</source>
        <translation>已填补 1 个缺口</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 gaps filled</source>
        <translation>已填补 %1 个缺口</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>1 gap previewed</source>
        <translation>已预览 1 个缺口</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 gaps previewed</source>
        <translation>已预览 %1 个缺口</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>, 1 sample</source>
        <translation>，1 个采样点</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>, %1 samples</source>
        <translation>，%1 个采样点</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>1 gap left open: %1</source>
        <translation>1 个缺口未填补：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 gaps left open (the first: %2)</source>
        <translation>%1 个缺口未填补（第一个：%2）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1; %2</source>
        <translation>%1；%2</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>%1 frames %2–%3</source>
        <translation>%1 第 %2–%3 帧</translation>
    </message>
    <message>
        <location line="+7"/>
        <source> and 1 more gap</source>
        <translation> 以及另外 1 个缺口</translation>
    </message>
    <message>
        <location line="+0"/>
        <source> and %1 more gaps</source>
        <translation> 以及另外 %1 个缺口</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Fill Past the Rules?</source>
        <translation>超出规则填补？</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Invent 1 sample: %1?</source>
        <translation>编造 1 个采样点：%1？</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Invent %1 samples: %2?</source>
        <translation>编造 %1 个采样点：%2？</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>These gaps are longer than the limit, at the take&apos;s ends or on a marker seen too rarely: nothing measured them.</source>
        <translation>这些缺口超过上限、位于拍摄数据两端或属于出现过少的标记点：没有任何测量数据。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Nothing filled: filling past the rules was not confirmed</source>
        <translation>未填补：未确认超出规则填补</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Fill 1 gap: %1</source>
        <translation>填补 1 个缺口：%1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Fill %1 gaps: %2</source>
        <translation>填补 %1 个缺口：%2</translation>
    </message>
</context>
<context>
    <name>mocap::ui::GapTableModel</name>
    <message>
        <location filename="../widgets/models/gap_table_model.cpp" line="+31"/>
        <source>Auto (best blend)</source>
        <translation>自动（最佳混合）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rigid neighbours</source>
        <translation>刚性邻近点</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PCA (marker correlations)</source>
        <translation>PCA（标记点相关性）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cubic spline</source>
        <translation>三次样条</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Linear</source>
        <translation>线性</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Paper method: three neighbours (Zhang et al., muscle mechanism)</source>
        <translation>论文方法：三个邻近点（Zhang et al.，肌肉机制）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Paper method: n neighbours (Zhang et al., muscle mechanism)</source>
        <translation>论文方法：n 个邻近点（Zhang et al.，肌肉机制）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Neighbour average (Guenter)</source>
        <translation>邻近点平均（Guenter）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Distance-weighted neighbours (Lin–Ouhyoung)</source>
        <translation>距离加权邻近点（Lin–Ouhyoung）</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Blends regression on the markers moving most alike and the rigid motion of the nearest ones, weighted by how well each predicts the marker&apos;s own data beside the gap</source>
        <translation>融合基于运动最相似标记点的回归与最近标记点的刚体运动，按各自对缺口旁该标记点自身数据的预测效果加权</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Carries the rigid motion of the nearest markers seen through the gap</source>
        <translation>沿用缺口期间可见的最近标记点的刚体运动</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rebuilds the gap from a low-rank model of how all markers move together</source>
        <translation>用所有标记点共同运动的低秩模型重建缺口</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A cubic curve through two seen samples on each side of the gap</source>
        <translation>穿过缺口两侧各两个可见采样点的三次曲线</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A straight line between the samples on each side of the gap</source>
        <translation>缺口两侧采样点之间的直线</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Follows the displacements of the three nearest markers, as skin moves with the muscle below it</source>
        <translation>跟随最近三个标记点的位移，如同皮肤随其下方肌肉运动</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Like three neighbours, with the n nearest markers weighted by distance</source>
        <translation>类似三个邻近点，但使用按距离加权的 n 个最近标记点</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Moves the marker by the average displacement of its nearest neighbours</source>
        <translation>按最近邻近点的平均位移移动该标记点</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Moves the marker by its neighbours&apos; displacements, nearer ones weighing more</source>
        <translation>按邻近点的位移移动该标记点，越近权重越大</translation>
    </message>
    <message>
        <location line="+272"/>
        <source>filled (%1)</source>
        <translation>已填补（%1）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>filled</source>
        <translation>已填补</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>previewed</source>
        <translation>已预览</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>cannot fill: %1</source>
        <translation>无法填补：%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>allowed: %1</source>
        <translation>已允许：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>open</source>
        <translation>未填补</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>Left open by the fill rules (%1). Check to fill it anyway: Fill asks before inventing its samples</source>
        <translation>被填补规则保留为未填补（%1）。勾选以仍然填补：填补前会先询问是否编造这些采样点</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Filled by: %1</source>
        <translation>填补方式：%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: %2. Double-click to choose how this gap is filled</source>
        <translation>%1：%2。双击以选择此缺口的填补方式</translation>
    </message>
    <message>
        <source>Fill a gap the rules leave open (too long, at the take&apos;s ends, a marker seen too rarely)</source>
        <translation type="vanished">填补规则保留为未填补的缺口（过长、位于拍摄数据两端、标记点出现过少）</translation>
    </message>
    <message>
        <source>Open, previewed, filled, or why it is not filled</source>
        <translation type="vanished">未填补、已预览、已填补，或不填补的原因</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Check the gaps to fill together</source>
        <translation>勾选要一起填补的缺口</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>First missing frame (the file&apos;s numbering)</source>
        <translation>第一个缺失帧（按文件中的编号）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Length in frames</source>
        <translation>长度（帧）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Length in seconds</source>
        <translation>长度（秒）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>How the gap is filled (double-click to choose)</source>
        <translation>缺口的填补方式（双击以选择）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Open, previewed, filled, or why it is not filled. A gap the rules leave open (too long, at the take&apos;s ends, a marker seen too rarely) has a box: check it to fill the gap anyway</source>
        <translation>未填充、预览中、已填充，或未填充的原因。规则保留未填的间隙（过长、位于拍摄两端、标记点很少可见）带有复选框：勾选即可仍然填充该间隙</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Marker</source>
        <translation>标记点</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>First</source>
        <translation>起始帧</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Frames</source>
        <translation>帧数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>s</source>
        <translation>s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Method</source>
        <translation>方法</translation>
    </message>
    <message>
        <source>Allow</source>
        <translation type="vanished">允许</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>State</source>
        <translation>状态</translation>
    </message>
</context>
<context>
    <name>mocap::ui::HeadMarkersProposalBar</name>
    <message>
        <location filename="../widgets/panels/head_markers_proposal_bar.cpp" line="+30"/>
        <source>The take names no head markers (root… or head…) and has none saved: these move together as one rigid body. Nothing uses them until you accept them.</source>
        <translation>此录制没有命名头部标记点（root… 或 head…），也没有保存：这些标记点作为一个刚体一起运动。在您接受之前不会使用它们。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Accept</source>
        <translation>接受</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Use these markers for head stabilization, the head-stabilized view, layout planning and the face mesh, and save them with the take (undoable)</source>
        <translation>将这些标记点用于头部稳定、头部稳定视图、布局规划和面部网格，并随录制保存（可撤销）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Choose…</source>
        <translation>选择…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Choose the head markers yourself (Marker ▸ Reference Markers…)</source>
        <translation>自行选择头部标记点（标记点 ▸ 参考标记点…）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Not now: no head markers for this take</source>
        <translation>暂不：此录制没有头部标记点</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>Head markers guessed: %1</source>
        <translation>推测的头部标记点：%1</translation>
    </message>
</context>
<context>
    <name>mocap::ui::HeadStabilizationStep</name>
    <message>
        <location filename="../widgets/panels/head_stabilization_step.cpp" line="-51"/>
        <source>Head-mounted markers that move only with the head: the head pose of every frame is measured on them.</source>
        <translation>仅随头部运动的头戴标记点：每一帧的头部姿态都基于它们测得。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Reference markers</source>
        <translation>参考标记点</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>First complete frame</source>
        <translation>第一个完整帧</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Frame whose head pose becomes the stabilized pose</source>
        <translation>以该帧的头部姿态作为稳定后的姿态</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reference frame</source>
        <translation>参考帧</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Moves all markers in all frames into the head frame: &quot;Selected markers only&quot; and &quot;Selected frame range only&quot; do not apply to this step.</source>
        <translation>将所有帧中的所有标记点移入头部坐标系：“仅限所选标记点”和“仅所选帧范围”不适用于此步骤。</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Stabilize head</source>
        <translation>稳定头部</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Head</source>
        <comment>the Cleaning panel&apos;s tab of Stabilize head</comment>
        <translation>头部</translation>
    </message>
</context>
<context>
    <name>mocap::ui::HeadStabilizedViewAction</name>
    <message>
        <location filename="../widgets/actions/head_stabilized_view_action.cpp" line="+19"/>
        <source>&amp;Head-Stabilized View</source>
        <translation>头部稳定视图(&amp;H)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Show the markers in the head frame of the reference markers (a view setting; the take is not changed)</source>
        <translation>在参考标记点的头部坐标系中显示标记点（仅为视图设置，不会更改动捕片段）</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>3D view in the lab frame</source>
        <translation>三维视图使用实验室坐标系</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Choose at least three reference markers first (Marker ▸ Reference Markers…).</source>
        <translation>请先选择至少三个参考标记点（标记点 ▸ 参考标记点…）。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Head-Stabilized View</source>
        <translation>头部稳定视图</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>3D view stabilized on the reference markers (Ctrl+B again for the lab frame)</source>
        <translation>三维视图已按参考标记点稳定（再按 Ctrl+B 返回实验室坐标系）</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>3D view back in the lab frame: the reference markers cannot carry a head pose</source>
        <translation>三维视图已返回实验室坐标系：参考标记点无法确定头部姿态</translation>
    </message>
</context>
<context>
    <name>mocap::ui::HistoryPanel</name>
    <message>
        <location filename="../widgets/panels/history_panel.cpp" line="+19"/>
        <location line="+7"/>
        <source>all</source>
        <translation>全部</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Processing history (saved with the take)</source>
        <translation>处理历史（随拍摄数据一起保存）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Step</source>
        <translation>步骤</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Parameters</source>
        <translation>参数</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Markers</source>
        <translation>标记点</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Frames</source>
        <translation>帧</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Samples</source>
        <translation>采样点</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Time</source>
        <translation>时间</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Undo history (this session)</source>
        <translation>撤销历史（本次会话）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&lt;opened take&gt;</source>
        <translation>&lt;已打开的拍摄数据&gt;</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>%1 by %2 at %3</source>
        <translation>%1，由 %2 于 %3 执行</translation>
    </message>
</context>
<context>
    <name>mocap::ui::JobProgressRow</name>
    <message>
        <source>about %1 s left</source>
        <translation type="vanished">剩余约 %1 秒</translation>
    </message>
    <message>
        <source>about %1 min left</source>
        <translation type="vanished">剩余约 %1 分钟</translation>
    </message>
    <message>
        <location filename="../widgets/panels/job_progress_row.cpp" line="+22"/>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop the computation (Esc)</source>
        <translation>停止计算（Esc）</translation>
    </message>
</context>
<context>
    <name>mocap::ui::JobRunner</name>
    <message>
        <location filename="../widgets/document/job_runner.cpp" line="+17"/>
        <source>about %1 s left</source>
        <translation>剩余约 %1 秒</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>about %1 min left</source>
        <translation>剩余约 %1 分钟</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>unknown error</source>
        <translation>未知错误</translation>
    </message>
</context>
<context>
    <name>mocap::ui::LabellingActions</name>
    <message>
        <location filename="../widgets/actions/labelling_actions.cpp" line="+38"/>
        <source>Tracking and labelling…</source>
        <translation>正在跟踪并标注…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Track and Label cancelled; the take is unchanged</source>
        <translation>跟踪并标注已取消，动捕片段未更改</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Track and Label</source>
        <translation>跟踪并标注</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Nothing to label: every marker has a label</source>
        <translation>没有可标注的内容：每个标记点都已有名称</translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>Nothing to label: none of the %n unlabelled fragment(s) matches a marker</source>
        <translation>
            <numerusform>没有可标注的内容：%n 个未标注片段均无法与标记点匹配</numerusform>
        </translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Track and label (%1 of %2 fragments labelled)</source>
        <translation>跟踪并标注（已标注 %2 个片段中的 %1 个）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 of %2 fragments labelled; %3 samples left unlabelled</source>
        <translation>已标注 %2 个片段中的 %1 个；%3 个采样未标注</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Looking for label swaps…</source>
        <translation>正在查找名称交换…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Swap search cancelled</source>
        <translation>交换查找已取消</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Fix Swaps</source>
        <translation>修复交换</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>No label swaps found</source>
        <translation>未发现名称交换</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>No swap accepted; the take is unchanged</source>
        <translation>未接受任何交换，动捕片段未更改</translation>
    </message>
    <message numerus="yes">
        <location line="+8"/>
        <source>Repair %n label swap(s)</source>
        <translation>
            <numerusform>修复 %n 处名称交换</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>mocap::ui::LayoutErrorPlot</name>
    <message>
        <location filename="../widgets/views/layout_error_plot.cpp" line="+56"/>
        <source>Click a marker count (or use ←/→) to show its layout</source>
        <translation>点击某个标记点数量（或使用 ←/→）以显示其布局</translation>
    </message>
    <message>
        <location line="+117"/>
        <source>Run the plan to see the error for each marker count.</source>
        <translation>运行规划以查看每个标记点数量的误差。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>markers</source>
        <translation>标记点数</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>PFA</source>
        <translation>PFA</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Greedy</source>
        <translation>贪心</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Random (mean)</source>
        <translation>随机（均值）</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Recommended</source>
        <translation>推荐</translation>
    </message>
    <message>
        <location line="+63"/>
        <source>Marker reconstruction RMSE (mm)</source>
        <translation>标记点重建 RMSE (mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Blend-weight MSE (key poses)</source>
        <translation>混合权重 MSE（关键姿势）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rig-weight MSE (blendshape rig)</source>
        <translation>绑定模型权重 MSE（混合形状绑定模型）</translation>
    </message>
    <message>
        <source>Blend-weight MSE</source>
        <translation type="vanished">混合权重 MSE</translation>
    </message>
</context>
<context>
    <name>mocap::ui::LayoutPlanningPanel</name>
    <message>
        <location filename="../widgets/panels/layout_planning_panel.cpp" line="+116"/>
        <source>detected</source>
        <translation>自动检测</translation>
    </message>
    <message>
        <location line="+61"/>
        <source>Take files planned together with the open take (they must have its markers)</source>
        <translation>与已打开的拍摄数据一起规划的拍摄数据文件（必须包含其标记点）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Add…</source>
        <translation>添加…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remove</source>
        <translation>移除</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>More takes:</source>
        <translation>更多拍摄数据：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Add takes</source>
        <translation>添加拍摄数据</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Motion capture (*.c3d *.trc);;All files (*)</source>
        <translation>动作捕捉 (*.c3d *.trc);;所有文件 (*)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>PFA (principal feature analysis)</source>
        <translation>PFA（主特征分析）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Greedy (least reconstruction error)</source>
        <translation>贪心（最小重建误差）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Method:</source>
        <translation>方法：</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Share of the motion&apos;s variance the PCA keeps (the paper: 0.98)</source>
        <translation>PCA 保留的运动方差比例（论文：0.98）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Variance kept:</source>
        <translation>保留方差：</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>k-means restarts per cluster count (the paper: 1000; fewer run faster)</source>
        <translation>每个聚类数的 k-means 重启次数（论文：1000；次数越少运行越快）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Restarts:</source>
        <translation>重启次数：</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>all</source>
        <translation>全部</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>to</source>
        <translation>至</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Clusters k:</source>
        <translation>聚类数 k：</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Seed:</source>
        <translation>随机种子：</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Random marker sets scored at every size, the baseline a plan must beat</source>
        <translation>在每个数量下评估的随机标记集：方案必须超越的基准</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Random sets:</source>
        <translation>随机集：</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>automatic</source>
        <translation>自动</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Key poses of the blendshape basis: frame numbers, comma-separated (TAKE:FRAME for a further take, TAKE from 1); blank: the most extreme frames</source>
        <translation>混合形状基的关键姿势：帧号，以逗号分隔（其他录制用 录制:帧，录制从 1 开始）；留空：最极端的帧</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Key poses:</source>
        <translation>关键姿势：</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>detected automatically</source>
        <translation>自动检测</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mirror pairs: a text file (two labels a line) or a marker-set file (.json)</source>
        <translation>镜像对：文本文件（每行两个名称）或标记点集文件（.json）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>…</source>
        <translation>…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Choose a pairs file</source>
        <translation>选择配对文件</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Pairs file:</source>
        <translation>配对文件：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Pairs file</source>
        <translation>配对文件</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pairs (*.txt *.json);;All files (*)</source>
        <translation>配对 (*.txt *.json);;所有文件 (*)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Head motion is removed with these markers before planning, and they are not planned over (a reduced capture still needs them).</source>
        <translation>在规划之前用这些标记点去除头部运动，且它们不参与规划（精简后的捕捉仍需要它们）。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>all but the reference markers</source>
        <translation>除参考标记外的全部</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Markers to plan over, comma-separated; * and ? match any run and any character (e.g. section1-*, lip?)</source>
        <translation>要规划的标记，以逗号分隔；* 和 ? 分别匹配任意长度和任意一个字符（例如 section1-*、lip?）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Plan markers:</source>
        <translation>规划标记：</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Markers left out of the plan, comma-separated; * and ? match any run and any character (unlabelled points and the reference markers always are)</source>
        <translation>不参与规划的标记，以逗号分隔；* 和 ? 分别匹配任意长度和任意一个字符（未标注的点和参考标记总是不参与）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Judge layouts on the blendshape rig</source>
        <translation>在混合形状绑定模型上评估布局</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Also solve the loaded rig&apos;s weights from each layout and from every bound marker, and plot their MSE (the seed paper&apos;s measure on a semantic rig; mocap pfa --rig)</source>
        <translation>同时从每个布局和所有已绑定标记点求解已加载绑定模型的权重，并绘制其 MSE（种子论文的度量，用于语义绑定模型；mocap pfa --rig）</translation>
    </message>
    <message>
        <location line="+167"/>
        <source>Judging on the rig needs a blendshape rig (Blendshape Solve panel) and the markers bound to its neutral (Face Mesh panel); or switch it off.</source>
        <translation>在绑定模型上评估需要一个混合形状绑定模型（混合形状求解面板）以及绑定到其中性形状的标记点（面部网格面板）；或关闭此选项。</translation>
    </message>
    <message>
        <location line="+102"/>
        <source>%1 markers, %2 frames (%7), %3 pairs (%4), %5 PCA components. Recommended: %6 markers.</source>
        <translation>%1 个标记点，%2 帧（%7），%3 对（%4），%5 个 PCA 分量。推荐：%6 个标记点。</translation>
    </message>
    <message numerus="yes">
        <location line="+7"/>
        <source>head motion removed with %n reference marker(s)</source>
        <translation>
            <numerusform>已用 %n 个参考标记点去除头部运动</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>head motion not removed: no reference markers</source>
        <translation>未去除头部运动：没有参考标记点</translation>
    </message>
    <message>
        <location line="-292"/>
        <source>Reference markers:</source>
        <translation>参考标记点：</translation>
    </message>
    <message>
        <location line="-32"/>
        <location line="+41"/>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Leave out:</source>
        <translation>排除：</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Run</source>
        <translation>运行</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation type="vanished">取消</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Marker</source>
        <translation>标记点</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Mirror</source>
        <translation>镜像</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Pair frequency</source>
        <translation>配对频率</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The selected layout&apos;s markers; the frequency is the share of k-means restarts that chose the marker&apos;s pair (PFA only)</source>
        <translation>所选布局的标记点；频率是选中该标记点所在配对的 k-means 重启次数所占比例（仅 PFA）</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Export Labels…</source>
        <translation>导出名称…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export Marker Set…</source>
        <translation>导出标记点集…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export Take…</source>
        <translation>导出拍摄数据…</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Export marker labels</source>
        <translation>导出标记点名称</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Label list (*.txt)</source>
        <translation>名称列表 (*.txt)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Export marker set</source>
        <translation>导出标记点集</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Marker set (*.json)</source>
        <translation>标记点集 (*.json)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Export reduced take</source>
        <translation>导出精简的拍摄数据</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>C3D (*.c3d);;TRC (*.trc)</source>
        <translation>C3D (*.c3d);;TRC (*.trc)</translation>
    </message>
    <message>
        <location line="+89"/>
        <source>A plan is already running.</source>
        <translation>已有规划正在运行。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Open a take first.</source>
        <translation>请先打开拍摄数据。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The smallest cluster count (%1) is larger than the largest (%2).</source>
        <translation>最小聚类数（%1）大于最大聚类数（%2）。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The pairs file %1 does not exist.</source>
        <translation>配对文件 %1 不存在。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Head motion needs at least three reference markers (Marker ▸ Reference Markers…).</source>
        <translation>去除头部运动至少需要三个参考标记点（标记点 ▸ 参考标记点…）。</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Planning…</source>
        <translation>正在规划…</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Key poses</source>
        <translation>关键姿势</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Plan markers</source>
        <translation>规划标记</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Leave out</source>
        <translation>排除</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location line="-191"/>
        <source>Cancelling…</source>
        <translation>正在取消…</translation>
    </message>
    <message>
        <location line="+235"/>
        <source>Planning failed: %1</source>
        <translation>规划失败：%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cancelled; the previous result is kept.</source>
        <translation>已取消，保留先前的结果。</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>%1 frames dropped for a missing marker; the PCA explains %2 % of the variance; recommended by the %3</source>
        <translation>因缺少标记点而丢弃 %1 帧；PCA 解释了 %2 % 的方差；推荐依据：%3</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Not judged on the rig: %1</source>
        <translation>未在绑定模型上评估：%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Judging on the rig was cancelled.</source>
        <translation>在绑定模型上的评估已取消。</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>PFA %1 · greedy %2 · random %3</source>
        <translation>PFA %1 · 贪心 %2 · 随机 %3</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Rig-weight MSE at %1 markers (%2 of them bound; all %3 bound markers: 0): %4</source>
        <translation>%1 个标记点时的绑定模型权重 MSE（其中 %2 个已绑定；全部 %3 个已绑定标记点：0）：%4</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+16"/>
        <location line="+27"/>
        <source>There is no layout to export: run the plan and pick a marker count.</source>
        <translation>没有可导出的布局：请运行规划并选择标记点数量。</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Could not write %1:
%2</source>
        <translation>无法写入 %1：
%2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Wrote %1</source>
        <translation>已写入 %1</translation>
    </message>
</context>
<context>
    <name>mocap::ui::LiveLinkOpenDialog</name>
    <message>
        <location filename="../widgets/dialogs/live_link_open_dialog.cpp" line="+34"/>
        <location line="+60"/>
        <source>Open Live Link Recording</source>
        <translation>打开 Live Link 录制</translation>
    </message>
    <message>
        <location line="-55"/>
        <source>The CSV the Live Link Face app recorded</source>
        <translation>Live Link Face 应用录制的 CSV</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Browse…</source>
        <translation>浏览(&amp;B)…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Recording:</source>
        <translation>录制(&amp;R):</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>By name (arkit_to_ict for ICT names)</source>
        <translation>按名称（ICT 名称使用 arkit_to_ict）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Map onto the rig:</source>
        <translation>映射到绑定模型(&amp;M):</translation>
    </message>
    <message>
        <location line="+49"/>
        <source>Live Link Face CSV (*.csv);;All files (*)</source>
        <translation>Live Link Face CSV (*.csv);;所有文件 (*)</translation>
    </message>
</context>
<context>
    <name>mocap::ui::LiveStreamPanel</name>
    <message>
        <location filename="../widgets/panels/live_stream_panel.cpp" line="+74"/>
        <source>Live Link Face (Unreal, MetaHuman)</source>
        <translation>Live Link Face（Unreal、MetaHuman）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>VMC / OSC (VSeeFace, Blender add-ons)</source>
        <translation>VMC / OSC（VSeeFace、Blender 插件）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Live Link Face: the datagrams Epic&apos;s iPhone app sends, the 52 ARKit curves and the head&apos;s turn.
VMC: OSC bundles of the weights under ARKit names, and the markers as trackers.</source>
        <translation>Live Link Face：Epic 的 iPhone 应用发送的数据报，52 条 ARKit 曲线和头部转动。
VMC：以 ARKit 名称发送权重的 OSC 包，以及作为跟踪器的标记点。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The computer the engine runs on: a name or an address</source>
        <translation>运行引擎的计算机：名称或地址</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The Live Link subject name the engine lists</source>
        <translation>引擎列出的 Live Link 主体名称</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Solved weights</source>
        <translation>求解的权重</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The Blendshape Solve dock&apos;s weights on ARKit&apos;s 52 curves (ICT FaceKit names by the shipped ict_to_arkit map)</source>
        <translation>Blendshape 求解面板的权重映射到 ARKit 的 52 条曲线（ICT FaceKit 名称通过自带的 ict_to_arkit 映射）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Markers (VMC)</source>
        <translation>标记点（VMC）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Each marker as a VMC tracker, in metres; a missing sample is not sent</source>
        <translation>每个标记点作为 VMC 跟踪器，单位为米；缺失的采样不发送</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The take&apos;s rate</source>
        <translation>拍摄的帧率</translation>
    </message>
    <message>
        <location line="+3"/>
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Datagrams per second; each carries the frame shown at that moment</source>
        <translation>每秒数据报数；每个携带当时显示的帧</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Start or stop the stream (Ctrl+Shift+L)</source>
        <translation>开始或停止流（Ctrl+Shift+L）</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Protocol</source>
        <translation>协议</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Host</source>
        <translation>主机</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Port</source>
        <translation>端口</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Subject</source>
        <translation>主体</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Send</source>
        <translation>发送</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Rate</source>
        <translation>速率</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Ctrl+Shift+L</source>
        <translation>Ctrl+Shift+L</translation>
    </message>
    <message>
        <location line="+84"/>
        <source>Connecting to %1…</source>
        <translation>正在连接 %1…</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+7"/>
        <source>Stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Start</source>
        <translation>开始</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Not streaming.</source>
        <translation>未在推流。</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Streaming to %1: %2 datagrams/s, %3 sent</source>
        <translation>正在推流到 %1：%2 个数据报/秒，已发送 %3 个</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>, %1 refused: %2</source>
        <translation>，%1 个被拒绝：%2</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Cannot stream: %1</source>
        <translation>无法推流：%1</translation>
    </message>
</context>
<context>
    <name>mocap::ui::ManualWindow</name>
    <message>
        <location filename="../widgets/dialogs/manual_window.cpp" line="+27"/>
        <source>Mocap Studio Manual</source>
        <translation>Mocap Studio 手册</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>The manual is not part of this build (:/manual/manual.md is missing).</source>
        <translation>此版本不包含手册（缺少 :/manual/manual.md）。</translation>
    </message>
</context>
<context>
    <name>mocap::ui::MarkerEditActions</name>
    <message>
        <location filename="../widgets/actions/marker_edit_actions.cpp" line="+30"/>
        <source>Select the markers to delete first</source>
        <translation>请先选择要删除的标记点</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Select the markers to average first</source>
        <translation>请先选择要平均的标记点</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+7"/>
        <source>Add Averaged Marker</source>
        <translation>添加平均标记点</translation>
    </message>
    <message>
        <location line="-6"/>
        <source>Label of the marker at the mean of %1:</source>
        <translation>位于 %1 平均位置的标记点名称：</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&apos;%1&apos; is empty or already a marker label; choose another.</source>
        <translation>“%1”为空或已是标记点名称，请另选一个。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Add averaged marker %1</source>
        <translation>添加平均标记点 %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Select exactly two markers and Shift-drag a frame range on the curves first</source>
        <translation>请先选择恰好两个标记点，并在曲线上按住 Shift 拖动选择帧范围</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Nothing to swap: both markers are gaps over the selected range</source>
        <translation>没有可交换的内容：两个标记点在所选范围内均为缺口</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Swap %1 and %2 over frames %3–%4</source>
        <translation>在第 %3–%4 帧交换 %1 和 %2</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Select markers and Shift-drag a frame range on the curves first</source>
        <translation>请先选择标记点，并在曲线上按住 Shift 拖动选取帧范围</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Nothing to delete: the selected range is already a gap</source>
        <translation>没有可删除的内容：所选范围已是缺口</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Delete frames %1–%2</source>
        <translation>删除第 %1–%2 帧</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Select the one marker whose label the point gets, then click the point</source>
        <translation>请选择一个标记点作为该点的名称，然后点击该点</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Label %1 as %2</source>
        <translation>将 %1 标注为 %2</translation>
    </message>
</context>
<context>
    <name>mocap::ui::MarkerTableModel</name>
    <message>
        <location filename="../widgets/models/marker_table_model.cpp" line="+72"/>
        <source>A model output (%1), not a marker: never cleaned; drawn and gap-listed only with View ▸ Show Model Outputs</source>
        <translation>模型输出（%1），不是标记点：从不清理；仅在 视图 ▸ 显示模型输出 时绘制并列入缺口列表</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Longest gap, in frames</source>
        <translation>最长缺口（帧）</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Marker</source>
        <translation>标记点</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Valid %</source>
        <translation>有效 %</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gaps</source>
        <translation>缺口</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Longest</source>
        <comment>the longest gap</comment>
        <translation>最长</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bad</source>
        <comment>bad points</comment>
        <translation>坏点</translation>
    </message>
    <message>
        <source>Longest gap</source>
        <translation type="vanished">最长缺口</translation>
    </message>
    <message>
        <location line="-12"/>
        <source>Bad points</source>
        <translation>坏点</translation>
    </message>
</context>
<context>
    <name>mocap::ui::MarkerView3d</name>
    <message>
        <location filename="../widgets/views/marker_view_3d.cpp" line="+273"/>
        <source>%1
%2, %3, %4 %5</source>
        <translation>%1
%2, %3, %4 %5</translation>
    </message>
    <message numerus="yes">
        <location line="-69"/>
        <source>Head-stabilized on %n marker(s) — Ctrl+B for the lab frame</source>
        <translation>
            <numerusform>已基于 %n 个标记点进行头部稳定 — 按 Ctrl+B 返回实验室坐标系</numerusform>
        </translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Camera follows the head</source>
        <translation>相机跟随头部</translation>
    </message>
</context>
<context>
    <name>mocap::ui::ModelOutputsNote</name>
    <message>
        <location filename="../widgets/views/model_outputs_note.cpp" line="+28"/>
        <source>%1 shown</source>
        <translation>%1 已显示</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 hidden</source>
        <translation>%1 已隐藏</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 shown; never cleaned</source>
        <translation>%1 已显示；从不清理</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 hidden; View ▸ Show Model Outputs</source>
        <translation>%1 已隐藏；视图 ▸ 显示模型输出</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Model outputs are joint angles, forces, moments, powers and virtual points (a model&apos;s segment axes, centre of mass) the capture software stored as points. They are kept and saved, but not cleaned, gap-listed or counted in statistics.</source>
        <translation>模型输出是采集软件以点形式存储的关节角度、力、力矩、功率和虚拟点（模型的节段轴、质心）。它们会被保留和保存，但不会被清理、列入缺口列表或计入统计。</translation>
    </message>
    <message>
        <source>Model outputs are joint angles, forces, moments and powers the capture software stored as points. They are kept and saved, but not cleaned, gap-listed or counted in statistics.</source>
        <translation type="vanished">模型输出是采集软件以点存储的关节角度、力、力矩和功率。它们会被保留和保存，但不会被清理、列入缺口列表或计入统计。</translation>
    </message>
</context>
<context>
    <name>mocap::ui::PreferencesDialog</name>
    <message>
        <location filename="../widgets/dialogs/preferences_dialog.cpp" line="+26"/>
        <source>Preferences</source>
        <translation>首选项</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Radius of the marker spheres as a share of the take&apos;s size</source>
        <translation>标记点球体半径占拍摄尺寸的比例</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Marker size:</source>
        <translation>标记点大小：</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Off</source>
        <translation>关闭</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Frames before and after the current one drawn as trails of the selected markers</source>
        <translation>作为所选标记点轨迹绘制的当前帧前后的帧数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Trail length (frames):</source>
        <translation>轨迹长度（帧）：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Y up</source>
        <translation>Y 轴向上</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Z up</source>
        <translation>Z 轴向上</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Up axis:</source>
        <translation>向上轴：</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Unit of the curve labels and read-outs; the take keeps its own units</source>
        <translation>曲线标签和读数的单位；拍摄保留其自身单位</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Display units:</source>
        <translation>显示单位：</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Used from the next start</source>
        <translation>下次启动时生效</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Language:</source>
        <translation>语言：</translation>
    </message>
    <message>
        <location line="+3"/>
        <source> min</source>
        <translation> 分钟</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>How often unsaved edits are copied to a recovery file</source>
        <translation>未保存的编辑复制到恢复文件的频率</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Autosave every:</source>
        <translation>自动保存间隔：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Captured samples:</source>
        <translation>采集的采样点：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Filled samples:</source>
        <translation>填充的采样点：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Smoothed samples:</source>
        <translation>平滑的采样点：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Edited samples:</source>
        <translation>编辑过的采样点：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Selection:</source>
        <translation>选中项：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bad points:</source>
        <translation>坏点：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>3D background:</source>
        <translation>三维背景：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Default Colours</source>
        <translation>默认颜色</translation>
    </message>
    <message>
        <location line="+58"/>
        <source>Language</source>
        <translation>语言</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The new language is used from the next start.</source>
        <translation>新语言将在下次启动时生效。</translation>
    </message>
</context>
<context>
    <name>mocap::ui::ReadWarningsButton</name>
    <message numerus="yes">
        <location filename="../widgets/dialogs/read_warnings_button.cpp" line="+55"/>
        <source>⚠ Incomplete, wrong data: %n warning(s)</source>
        <translation>
            <numerusform>⚠ 不完整、数据错误：%n 条警告</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>⚠ Incomplete: %n warning(s)</source>
        <translation>
            <numerusform>⚠ 不完整：%n 条警告</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>⚠ Wrong data: %n warning(s)</source>
        <translation>
            <numerusform>⚠ 数据错误：%n 条警告</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>⚠ %n warning(s)</source>
        <translation>
            <numerusform>⚠ %n 条警告</numerusform>
        </translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Show every warning from reading the file</source>
        <translation>显示读取文件时的所有警告</translation>
    </message>
</context>
<context>
    <name>mocap::ui::ReadWarningsDialog</name>
    <message>
        <location filename="../widgets/dialogs/read_warnings_dialog.cpp" line="+31"/>
        <source>%1 is incomplete and has wrong data</source>
        <translation>%1 不完整且含有错误数据</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 is incomplete</source>
        <translation>%1 不完整</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 has wrong data</source>
        <translation>%1 含有错误数据</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Warnings reading %1</source>
        <translation>读取 %1 时的警告</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&lt;b&gt;Data is missing from %1, and some that was read is wrong.&lt;/b&gt; The take opened with what could be read; the rest is not in it, and the samples named below are not what was captured. Saving writes only what was read, with these findings.</source>
        <translation>&lt;b&gt;%1 中缺少数据，且部分已读取的数据有误。&lt;/b&gt;拍摄已按可读取的内容打开；其余部分不在其中，下列采样并非实际采集的数据。保存时只写入已读取的内容，并附上这些发现。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&lt;b&gt;Data is missing from %1.&lt;/b&gt; The take opened with what could be read; the rest is not in it. Saving writes only what was read.</source>
        <translation>&lt;b&gt;%1 中缺少数据。&lt;/b&gt;拍摄数据已按可读取的部分打开，其余部分不在其中。保存时只会写入已读取的内容。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&lt;b&gt;Some data in %1 is wrong.&lt;/b&gt; The take opened with every sample as it was read, but the samples named below are not what was captured. Saving keeps them as they are, with this finding.</source>
        <translation>&lt;b&gt;%1 中有部分数据错误。&lt;/b&gt;拍摄已按读取时的每个采样打开，但下列采样并非实际采集的数据。保存时保持原样，并附上此发现。</translation>
    </message>
    <message numerus="yes">
        <location line="+4"/>
        <source>%n warning(s) while reading %1. The take opened; these are quirks of the file that were tolerated.</source>
        <translation>
            <numerusform>读取 %1 时出现 %n 条警告。拍摄数据已打开；这些是文件中已被容忍的不规范之处。</numerusform>
        </translation>
    </message>
    <message>
        <location line="+11"/>
        <source>incomplete, wrong data</source>
        <translation>不完整、数据错误</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>incomplete</source>
        <translation>不完整</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>wrong data</source>
        <translation>数据错误</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>%1 (acknowledged)</source>
        <translation>%1（已确认）</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>I understand</source>
        <translation>我知道了</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Close</source>
        <translation>关闭</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Acknowledge</source>
        <translation>确认</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Record in the take&apos;s history that a person has seen these findings (undoable): they stay in the history and in mocap info, but reading a saved copy no longer raises them as warnings</source>
        <translation>在拍摄的历史中记录已有人查看这些发现（可撤销）：它们仍保留在历史和 mocap info 中，但读取已保存的副本时不再作为警告提出</translation>
    </message>
</context>
<context>
    <name>mocap::ui::ReferenceMarkerActions</name>
    <message>
        <location filename="../widgets/actions/reference_marker_actions.cpp" line="+39"/>
        <source>Reference markers unchanged</source>
        <translation>参考标记点未更改</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Select at least three head-mounted markers first</source>
        <translation>请先选择至少三个头戴标记点</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The selected markers already are the reference markers</source>
        <translation>所选标记点已经是参考标记点</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Head markers set; Edit ▸ Undo takes them back</source>
        <translation>已设置头部标记点；编辑 ▸ 撤销可取消</translation>
    </message>
</context>
<context>
    <name>mocap::ui::ReferenceMarkersDialog</name>
    <message>
        <location filename="../widgets/dialogs/reference_markers_dialog.cpp" line="+34"/>
        <source>Reference Markers</source>
        <translation>参考标记点</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Head-mounted markers that move only with the head (at least three). Head stabilization, the head-stabilized view, layout planning and the face mesh remove the head&apos;s motion with them; layout planning leaves them out.</source>
        <translation>仅随头部运动的头戴标记点（至少三个）。头部稳定、头部稳定视图、布局规划和面部网格用它们去除头部运动；布局规划不包含它们。</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Valid in %1 % of the frames</source>
        <translation>在 %1 % 的帧中有效</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>A model output, not a marker</source>
        <translation>模型输出，不是标记点</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&amp;Guess</source>
        <translation>自动推测(&amp;G)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Markers named root… or head…, else the markers that move together as one rigid body</source>
        <translation>名称为 root… 或 head… 的标记点；若没有，则取作为一个刚体共同运动的标记点</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Use &amp;Selection</source>
        <translation>使用所选(&amp;S)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>C&amp;lear</source>
        <translation>清除(&amp;L)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>No reference markers: head motion is not removed anywhere</source>
        <translation>不使用参考标记点：任何地方都不去除头部运动</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>No reference markers: head motion is not removed, and layout planning plans every labelled marker.</source>
        <translation>没有参考标记点：不去除头部运动，布局规划将纳入所有已标注的标记点。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: a head pose needs at least three markers (or none).</source>
        <translation>%1：头部姿态至少需要三个标记点（或一个都不选）。</translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>%n reference marker(s): %1</source>
        <translation>
            <numerusform>%n 个参考标记点：%1</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>mocap::ui::ReferenceMarkersRow</name>
    <message>
        <location filename="../widgets/panels/reference_markers_row.cpp" line="+21"/>
        <source>One set per take, chosen in Marker ▸ Reference Markers…</source>
        <translation>每个拍摄数据一组，在“标记点 ▸ 参考标记点…”中选择</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Edit…</source>
        <translation>编辑…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Choose the reference markers (Marker ▸ Reference Markers…)</source>
        <translation>选择参考标记点（标记点 ▸ 参考标记点…）</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>none (head motion is not removed)</source>
        <translation>无（不去除头部运动）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
</context>
<context>
    <name>mocap::ui::ReferenceVideoPanel</name>
    <message>
        <location filename="../widgets/panels/reference_video_panel.cpp" line="+48"/>
        <source>The take&apos;s reference videos: the one picked here is shown</source>
        <translation>录制的参考视频：显示此处选中的视频</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Add Reference Video…</source>
        <translation>添加参考视频…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A video of the session (MP4, MOV, AVI, MKV) shown at the take&apos;s current frame</source>
        <translation>拍摄现场的视频（MP4、MOV、AVI、MKV），按拍摄的当前帧显示</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Locate…</source>
        <translation>定位…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Find a video that is no longer where the take remembers it</source>
        <translation>查找已不在录制所记位置的视频</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Remove</source>
        <translation>移除</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remove the shown video from the take</source>
        <translation>从录制中移除所显示的视频</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Offset:</source>
        <translation>偏移：</translation>
    </message>
    <message>
        <location line="-14"/>
        <source> s</source>
        <translation>秒</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Video time at the take&apos;s first frame: video time = (take frame − first) / take rate + offset</source>
        <translation>拍摄第一帧时的视频时间：视频时间 = (拍摄帧 − 第一帧) / 拍摄帧率 + 偏移</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>−1 frame</source>
        <translation>−1 帧</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Show the video one of its frames earlier (Alt+,)</source>
        <translation>将视频提前一帧显示 (Alt+,)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Show the video one of its frames later (Alt+.)</source>
        <translation>将视频推后一帧显示 (Alt+.)</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Video frame:</source>
        <translation>视频帧：</translation>
    </message>
    <message>
        <location line="-16"/>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The video frame shown. Type or step it to hold the video at a moment, step the take to the same moment, then press Sync here</source>
        <translation>所显示的视频帧。输入或步进以将视频停在某一时刻，将录制步进到同一时刻，然后按“在此同步”</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Sync here</source>
        <translation>在此同步</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Set the offset so the held video frame shows at the take&apos;s current frame</source>
        <translation>设置偏移，使停住的视频帧显示在录制的当前帧</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Follow take</source>
        <translation>跟随录制</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop holding the video: show the frame for the take&apos;s current frame again</source>
        <translation>不再停住视频：重新显示录制当前帧对应的视频帧</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Event:</source>
        <translation>事件：</translation>
    </message>
    <message>
        <location line="-10"/>
        <source>The take&apos;s events (C3D EVENT parameters); a sync event is picked first</source>
        <translation>录制的事件（C3D EVENT 参数）；优先选择同步事件</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Sync to event</source>
        <translation>同步到事件</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Set the offset so the event shows the video&apos;s first frame, or the held one</source>
        <translation>设置偏移，使事件处显示视频的第一帧或停住的帧</translation>
    </message>
    <message>
        <location line="+278"/>
        <source>Locate %1</source>
        <translation>定位 %1</translation>
    </message>
    <message>
        <source>Move the video one of its frames earlier (Alt+,)</source>
        <translation type="vanished">将视频提前一帧（Alt+,）</translation>
    </message>
    <message>
        <location line="-314"/>
        <source>+1 frame</source>
        <translation>+1 帧</translation>
    </message>
    <message>
        <source>Move the video one of its frames later (Alt+.)</source>
        <translation type="vanished">将视频推后一帧（Alt+.）</translation>
    </message>
    <message>
        <source>Cannot show %1: %2</source>
        <translation type="vanished">无法显示 %1：%2</translation>
    </message>
    <message>
        <location line="+154"/>
        <source>First hold the video at a moment: type its frame or step it, then step the take to the same moment</source>
        <translation>请先将视频停在某一时刻：输入或步进其帧，然后将录制步进到同一时刻</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Video frame %1 now shows at take frame %2 (offset %3 s)</source>
        <translation>视频第 %1 帧现在显示在录制第 %2 帧（偏移 %3 秒）</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>The event “%1” (%2 s) lies outside the take&apos;s frames</source>
        <translation>事件“%1”（%2 秒）在录制的帧范围之外</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Video frame %1 now shows at the event “%2” (take frame %3; offset %4 s)</source>
        <translation>视频第 %1 帧现在显示在事件“%2”处（录制第 %3 帧；偏移 %4 秒）</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>%1 (missing)</source>
        <translation>%1（缺失）</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+3"/>
        <source>No reference video</source>
        <translation>无参考视频</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>%1 is not available</source>
        <translation>%1 不可用</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: %2×%3, %4 fps, %5 frames (%6 s), %7</source>
        <translation>%1：%2×%3，%4 fps，%5 帧（%6 秒），%7</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>; variable frame rate: frames are placed by their timestamps</source>
        <translation>；可变帧率：按时间戳放置帧</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>%1%2 · frame %3</source>
        <translation>%1%2 · 第 %3 帧</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The take has no events</source>
        <translation>录制没有事件</translation>
    </message>
    <message>
        <source>The videos remembered for this take cannot be read (%1); that file is left as it is and changes here are not remembered.</source>
        <translation type="vanished">无法读取为此录制记住的视频（%1）；该文件保持不变，此处的更改不会被记住。</translation>
    </message>
    <message>
        <source>%1 is missing: the take remembers it at %2. Locate… finds it; until then it stays linked to the take.</source>
        <translation type="vanished">%1 缺失：录制记住它位于 %2。“定位…”可找到它；在此之前它仍与录制关联。</translation>
    </message>
    <message numerus="yes">
        <location line="+10"/>
        <source>%n of the take&apos;s reference videos cannot be found where the take remembers them. Pick one and press Locate… to find it; they stay remembered meanwhile.</source>
        <translation>
            <numerusform>录制的 %n 个参考视频不在所记的位置。选择一个并按“定位…”查找；在此期间它们仍被记住。</numerusform>
        </translation>
    </message>
    <message>
        <source>Cannot remember the videos beside the take: %1</source>
        <translation type="vanished">无法在录制旁记住视频：%1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Add reference video</source>
        <translation>添加参考视频</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+16"/>
        <source>Videos (*.mp4 *.mov *.avi *.mkv *.m4v *.webm);;All files (*)</source>
        <translation>视频 (*.mp4 *.mov *.avi *.mkv *.m4v *.webm);;所有文件 (*)</translation>
    </message>
</context>
<context>
    <name>mocap::ui::ReferenceVideos</name>
    <message>
        <location filename="../widgets/document/reference_videos.cpp" line="+125"/>
        <location line="+27"/>
        <location line="+18"/>
        <source>Cannot show %1: %2</source>
        <translation>无法显示 %1：%2</translation>
    </message>
    <message>
        <location line="-4"/>
        <source>%1 is missing: the take remembers it at %2. Locate… finds it; until then it stays linked to the take.</source>
        <translation>%1 缺失：录制记住它位于 %2。“定位…”可找到它；在此之前它仍与录制关联。</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>The videos remembered for this take cannot be read (%1); that file is left as it is and changes here are not remembered.</source>
        <translation>无法读取为此录制记住的视频（%1）；该文件保持不变，此处的更改不会被记住。</translation>
    </message>
    <message>
        <location line="+64"/>
        <source>Cannot remember the videos beside the take: %1</source>
        <translation>无法在录制旁记住视频：%1</translation>
    </message>
</context>
<context>
    <name>mocap::ui::RetargetMapChooser</name>
    <message>
        <location filename="../widgets/dialogs/retarget_map_chooser.cpp" line="+31"/>
        <source>%1 (shipped)</source>
        <translation>%1（内置）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Map file…</source>
        <translation>映射文件…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Our shape names onto the target rig&apos;s channels, with gains, offsets and clamps (as the command line&apos;s --map)</source>
        <translation>将我们的形状名称映射到目标绑定模型的通道，含增益、偏移和钳位（同命令行的 --map）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Br&amp;owse…</source>
        <translation>浏览(&amp;O)…</translation>
    </message>
    <message>
        <location line="+84"/>
        <source>Retarget map</source>
        <translation>重定向映射</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Retarget maps (*.json);;All files (*)</source>
        <translation>重定向映射 (*.json);;所有文件 (*)</translation>
    </message>
</context>
<context>
    <name>mocap::ui::RetargetSection</name>
    <message>
        <location filename="../widgets/panels/retarget_section.cpp" line="+56"/>
        <source>Retarget</source>
        <translation>重定向</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>No map</source>
        <translation>无映射</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save Map As…</source>
        <translation>映射另存为…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The map with its edited gains as JSON, for Export Rig and mocap solve --map</source>
        <translation>将编辑过增益的映射保存为 JSON，供导出绑定模型和 mocap solve --map 使用</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Channel</source>
        <translation>通道</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Source</source>
        <translation>来源</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Gain</source>
        <translation>增益</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Peak</source>
        <translation>峰值</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>Cannot read the map: %1</source>
        <translation>无法读取映射：%1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Load a map first.</source>
        <translation>请先加载映射。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Cannot write the map: %1</source>
        <translation>无法写入映射：%1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Saved the map to %1.</source>
        <translation>已将映射保存到 %1。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>That row has no source to scale.</source>
        <translation>该行没有可缩放的来源。</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+91"/>
        <source>A gain must be a number.</source>
        <translation>增益必须是数字。</translation>
    </message>
    <message>
        <location line="-86"/>
        <source>Gain of %1 in %2</source>
        <translation>%2 中 %1 的增益</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>(none)</source>
        <translation>（无）</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Load a map to see the solve under a target rig&apos;s channels.</source>
        <translation>加载映射，以查看目标绑定模型通道下的求解结果。</translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>%n channel(s). Load a rig to map its curves.</source>
        <translation>
            <numerusform>%n 个通道。加载绑定模型以映射其曲线。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+5"/>
        <source>%n channel(s) from the rig&apos;s shapes.</source>
        <translation>
            <numerusform>%n 个通道，来自绑定模型的形状。</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The map does not fit the rig: %1</source>
        <translation>映射与绑定模型不符：%1</translation>
    </message>
    <message>
        <location line="+57"/>
        <source>Save Retarget Map</source>
        <translation>保存重定向映射</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Retarget maps (*.json)</source>
        <translation>重定向映射 (*.json)</translation>
    </message>
</context>
<context>
    <name>mocap::ui::ReviewExportDialog</name>
    <message>
        <location filename="../widgets/actions/review_video_export.cpp" line="+34"/>
        <source>Rendering the review video…</source>
        <translation>正在渲染审阅视频…</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Review video cancelled; nothing was written.</source>
        <translation>审阅视频已取消；未写入任何内容。</translation>
    </message>
    <message>
        <location line="+3"/>
        <location filename="../widgets/dialogs/review_export_dialog.cpp" line="+38"/>
        <location line="+55"/>
        <source>Export Review Video</source>
        <translation>导出审阅视频</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The review video was not written: %1</source>
        <translation>审阅视频未写入：%1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>This system has no MP4 encoder, so the video was written as Motion JPEG AVI: %1</source>
        <translation>此系统没有 MP4 编码器，因此视频以 Motion JPEG AVI 写入：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Wrote %1 (%2 frames, %3)</source>
        <translation>已写入 %1（%2 帧，%3）</translation>
    </message>
    <message>
        <location filename="../widgets/dialogs/review_export_dialog.cpp" line="-45"/>
        <source>Browse…</source>
        <translation>浏览…</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 × %2</source>
        <translation>%1 × %2</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>to</source>
        <translation>至</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Reference video beside the 3D view</source>
        <translation>在 3D 视图旁显示参考视频</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Add a reference video in the Reference Video dock to draw it beside the view.</source>
        <translation>在“参考视频”面板中添加参考视频，即可将其显示在视图旁。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Export</source>
        <translation>导出</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>File:</source>
        <translation>文件：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Size:</source>
        <translation>尺寸：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Frames:</source>
        <translation>帧：</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>MP4 video (*.mp4);;Motion JPEG AVI (*.avi)</source>
        <translation>MP4 视频 (*.mp4);;Motion JPEG AVI (*.avi)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Name the video .mp4 or .avi.</source>
        <translation>请将视频命名为 .mp4 或 .avi。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The first frame comes after the last.</source>
        <translation>第一帧在最后一帧之后。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 exists. Replace it?</source>
        <translation>%1 已存在。要替换吗？</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>untitled take</source>
        <translation>未命名录制</translation>
    </message>
</context>
<context>
    <name>mocap::ui::RigExportDialog</name>
    <message>
        <location filename="../widgets/dialogs/rig_export_dialog.cpp" line="+90"/>
        <location line="+246"/>
        <source>Export Rig</source>
        <translation>导出绑定模型</translation>
    </message>
    <message>
        <location line="-233"/>
        <source>FBX rig with animated blend shapes (.fbx)</source>
        <translation>带动画混合形状的 FBX 绑定模型 (.fbx)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>glTF rig with animated morph targets (.glb)</source>
        <translation>带动画变形目标的 glTF 绑定模型 (.glb)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Weight curves, one column per shape (.csv)</source>
        <translation>权重曲线，每个形状一列 (.csv)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Live Link Face CSV (.csv)</source>
        <translation>Live Link Face CSV (.csv)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Format:</source>
        <translation>格式(&amp;F):</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Browse…</source>
        <translation>浏览(&amp;B)…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Output:</source>
        <translation>输出(&amp;O):</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>None (the rig&apos;s own names)</source>
        <translation>无（绑定模型自身的名称）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>For Live Link Face, none means the default map for the rig&apos;s names</source>
        <translation>对 Live Link Face 而言，“无”表示按绑定模型名称的默认映射</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Retarget &amp;map:</source>
        <translation>重定向映射(&amp;M):</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Keys:</source>
        <translation>关键帧(&amp;K):</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Y up</source>
        <translation>Y 向上</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Z up</source>
        <translation>Z 向上</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The units the rig&apos;s coordinates are in, declared in the FBX&apos;s global settings</source>
        <translation>绑定模型坐标所用的单位，写入 FBX 的全局设置</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>FBX &amp;axes:</source>
        <translation>FBX 坐标轴(&amp;A):</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>&amp;Export</source>
        <translation>导出(&amp;E)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Close</source>
        <translation>关闭</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Keep the fewest keys within</source>
        <translation>保留最少关键帧，误差不超过</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Each curve keeps the fewest keys whose linear interpolation stays within the tolerance of every frame (as mocap solve --reduce); otherwise every frame is a key</source>
        <translation>每条曲线保留最少的关键帧，使其线性插值与每一帧的差不超过容差（同 mocap solve --reduce）；否则每帧都是关键帧</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>weight units</source>
        <translation>权重单位</translation>
    </message>
    <message>
        <location line="+83"/>
        <source>Retarget section&apos;s: %1, gains edited</source>
        <translation>重定向区的：%1，增益已编辑</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Retarget section&apos;s: %1</source>
        <translation>重定向区的：%1</translation>
    </message>
    <message>
        <location line="+65"/>
        <source>FBX (*.fbx)</source>
        <translation>FBX (*.fbx)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>glTF binary (*.glb)</source>
        <translation>glTF 二进制 (*.glb)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CSV (*.csv)</source>
        <translation>CSV (*.csv)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Solve the take first.</source>
        <translation>请先求解拍摄。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Choose the map file.</source>
        <translation>请选择映射文件。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The map cannot be used: %1</source>
        <translation>无法使用该映射：%1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Choose where to export.</source>
        <translation>请选择导出位置。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The folder %1 does not exist.</source>
        <translation>文件夹 %1 不存在。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Replace File?</source>
        <translation>替换文件？</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Replace %1?</source>
        <translation>替换 %1？</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Not exported: the existing file is kept.</source>
        <translation>未导出：保留现有文件。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Export failed: %1</source>
        <translation>导出失败：%1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Wrote %1.</source>
        <translation>已写入 %1。</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Every frame is a key: %1 frames.</source>
        <translation>每帧都是关键帧：%1 帧。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Kept %1 of %2 keys (%3 %), largest error %4 (tolerance %5).</source>
        <translation>保留了 %2 个关键帧中的 %1 个（%3 %），最大误差 %4（容差 %5）。</translation>
    </message>
</context>
<context>
    <name>mocap::ui::SmoothingStep</name>
    <message>
        <location filename="../widgets/panels/smoothing_step.cpp" line="-105"/>
        <source>GCV smoothing spline (Woltring)</source>
        <translation>GCV 平滑样条（Woltring）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>B-spline (Zhang et al., smoothing)</source>
        <translation>B 样条（Zhang et al.，平滑）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Butterworth (zero lag)</source>
        <translation>Butterworth（零相位延迟）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Savitzky–Golay</source>
        <translation>Savitzky–Golay</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A smoothing spline whose stiffness is chosen per marker by generalized cross-validation: no setting to tune</source>
        <translation>平滑样条，其刚度按标记点由广义交叉验证选择：无需调参</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A least-squares B-spline with knots every few frames (the paper&apos;s smoothing)</source>
        <translation>每隔数帧设一个节点的最小二乘 B 样条（论文的平滑方法）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A low-pass filter run forwards and backwards, so nothing lags; cuts motion faster than the cutoff</source>
        <translation>正反向各运行一次的低通滤波器，因而没有滞后；滤除快于截止频率的运动</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A polynomial fitted in a sliding window: keeps peaks sharper than a low-pass filter</source>
        <translation>在滑动窗口中拟合多项式：比低通滤波器更能保留峰值</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Method</source>
        <translation>方法</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>B-spline degree: 3 is cubic, the paper&apos;s &quot;third order&quot;</source>
        <translation>B 样条次数：3 为三次，即论文中的“三阶”</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Degree</source>
        <translation>次数</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+11"/>
        <source> frames</source>
        <translation> 帧</translation>
    </message>
    <message>
        <location line="-10"/>
        <source>Knot spacing</source>
        <translation>节点间距</translation>
    </message>
    <message>
        <location line="+4"/>
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cutoff</source>
        <translation>截止频率</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Window</source>
        <translation>窗口</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Smoothing</source>
        <translation>平滑</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>1 sample smoothed</source>
        <translation>已平滑 1 个采样点</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 samples smoothed</source>
        <translation>已平滑 %1 个采样点</translation>
    </message>
</context>
<context>
    <name>mocap::ui::SpikeStep</name>
    <message>
        <location filename="../widgets/panels/spike_step.cpp" line="-97"/>
        <source>Robust (local fit + MAD)</source>
        <translation>稳健（局部拟合 + MAD）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Judges each sample against a robust local fit of its neighbours</source>
        <translation>依据相邻采样点的稳健局部拟合来判断每个采样点</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>Paper method: step test (Zhang et al., bad points)</source>
        <translation>论文方法：步长检验（Zhang et al.，坏点）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Flags a sample whose steps to both neighbours exceed a multiple of the mean step (the paper as written, one pass); repairs it from its neighbours</source>
        <translation>标记与两侧邻点的步长都超过平均步长若干倍的采样点（按论文原样，一遍）；并用其邻点修复</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Method</source>
        <translation>方法</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Paper: a sample is bad when both adjacent steps exceed this multiple of the mean step</source>
        <translation>论文：当前后两步的位移均超过平均步长的此倍数时，该采样点判为坏点</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Factor</source>
        <translation>倍数</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Robust: flag samples this many robust standard deviations off the local fit</source>
        <translation>稳健：偏离局部拟合超过此数量个稳健标准差的采样点将被标为坏点</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Threshold</source>
        <translation>阈值</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Look again until nothing new</source>
        <translation>反复检测直到无新发现</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A glitch longer than a few frames is found a part at a time, its worst samples first, so detecting again after a repair finds the rest beside the repaired samples. On, the robust detector repeats itself on the repaired curve until it finds nothing new: whole glitches are flagged at once (more flags), and a second detection finds next to nothing.</source>
        <translation>持续超过几帧的毛刺会被分段发现，最严重的采样点优先，因此修复后再次检测会在已修复采样点旁边找到其余部分。开启后，稳健检测器会在修复后的曲线上反复检测，直到没有新发现：整个毛刺会被一次性标记（标记更多），再次检测时几乎不会再有发现。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Click to go to a flag; uncheck to keep that sample</source>
        <translation>单击跳转到该坏点；取消勾选可保留该采样点</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Bad points</source>
        <translation>坏点</translation>
    </message>
    <message>
        <location line="+57"/>
        <source>%1 at frame %2</source>
        <translation>%1，第 %2 帧</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>1 sample repaired</source>
        <translation>已修复 1 个采样点</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 samples repaired</source>
        <translation>已修复 %1 个采样点</translation>
    </message>
</context>
<context>
    <name>mocap::ui::StudioSession</name>
    <message>
        <location filename="../widgets/document/studio_session.cpp" line="+150"/>
        <source>the binding</source>
        <translation>绑定</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the binding: %1</source>
        <translation>绑定：%1</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>the actor</source>
        <translation>演员</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the retarget map</source>
        <translation>重定向映射</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>the weight curves: they were made for a rig that is not loaded</source>
        <translation>权重曲线：它们是为未加载的绑定制作的</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the weight curves: %1 frames solved, the take has %2</source>
        <translation>权重曲线：已求解 %1 帧，拍摄有 %2 帧</translation>
    </message>
</context>
<context>
    <name>mocap::ui::SwapReviewDialog</name>
    <message>
        <location filename="../widgets/dialogs/swap_review_dialog.cpp" line="+16"/>
        <source>Review Label Swaps</source>
        <translation>检查名称交换</translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>%n swap(s) found. Uncheck the ones to leave as they are; double-click one to see its frame.</source>
        <translation>
            <numerusform>发现 %n 处交换。取消勾选要保留原样的项；双击可查看其帧。</numerusform>
        </translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Frame %1: %2 ↔ %3 (jump %4 mm, %5 mm when exchanged)</source>
        <translation>第 %1 帧：%2 ↔ %3（跳变 %4 mm，交换后 %5 mm）</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Repair Checked</source>
        <translation>修复已勾选项</translation>
    </message>
</context>
<context>
    <name>mocap::ui::TakeFileActions</name>
    <message>
        <location filename="../widgets/actions/take_file_actions.cpp" line="+36"/>
        <source>Opening %1…</source>
        <translation>正在打开 %1…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cancelled</source>
        <translation>已取消</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Cannot open file</source>
        <translation>无法打开文件</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Open take</source>
        <translation>打开动捕片段</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Motion capture (*.c3d *.trc);;All files (*)</source>
        <translation>动作捕捉文件 (*.c3d *.trc);;所有文件 (*)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Overwrite the original?</source>
        <translation>覆盖原始文件？</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save over %1? The original capture is replaced by the edited take.</source>
        <translation>要覆盖 %1 吗？原始捕捉数据将被编辑后的动捕片段替换。</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+12"/>
        <source>Cannot save</source>
        <translation>无法保存</translation>
    </message>
    <message>
        <location line="-6"/>
        <source>Save take as</source>
        <translation>动捕片段另存为</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>C3D (*.c3d);;TRC (*.trc)</source>
        <translation>C3D (*.c3d);;TRC (*.trc)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Saved %1</source>
        <translation>已保存 %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Export</source>
        <translation>导出</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>C3D (*.c3d);;TRC (*.trc);;CSV (*.csv);;BVH (*.bvh);;FBX markers (*.fbx)</source>
        <translation>C3D (*.c3d);;TRC (*.trc);;CSV (*.csv);;BVH (*.bvh);;FBX 标记点 (*.fbx)</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Cannot export</source>
        <translation>无法导出</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Exported %1</source>
        <translation>已导出 %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 — note: %2</source>
        <translation>%1 — 注意：%2</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Unsaved edits</source>
        <translation>未保存的修改</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>The take has unsaved edits. Save them?</source>
        <translation>动捕片段有未保存的修改。是否保存？</translation>
    </message>
</context>
<context>
    <name>mocap::ui::TimelineWidget</name>
    <message>
        <location filename="../widgets/views/timeline_widget.cpp" line="+49"/>
        <source>Dark: gaps, red: bad points under review — of the selected markers, or of all when none is selected. Yellow: the selected frame range.</source>
        <translation>深色：缺口；红色：待检查的坏点 — 针对所选标记点，未选择时针对全部标记点。黄色：所选帧范围。</translation>
    </message>
    <message>
        <location line="+134"/>
        <source>Previous gap</source>
        <translation>上一个缺口</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Previous frame (Left)</source>
        <translation>上一帧（左方向键）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Play / pause (Space)</source>
        <translation>播放/暂停（空格键）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Next frame (Right)</source>
        <translation>下一帧（右方向键）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Next gap</source>
        <translation>下一个缺口</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Loop</source>
        <translation>循环播放</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Frame</source>
        <translation>帧</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Playback speed</source>
        <translation>播放速度</translation>
    </message>
    <message>
        <location line="+145"/>
        <source>No gap after this frame</source>
        <translation>此帧之后没有缺口</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>No gap before this frame</source>
        <translation>此帧之前没有缺口</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Gap of %1 at frame %2 (%3 frames)</source>
        <translation>%1 在第 %2 帧处的缺口（%3 帧）</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>No bad point after this frame</source>
        <translation>此帧之后没有坏点</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>No bad point before this frame</source>
        <translation>此帧之前没有坏点</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Bad point at frame %1: %2</source>
        <translation>第 %1 帧的坏点：%2</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1, %2 %3 off the mid-point of its neighbours</source>
        <translation>%1，偏离相邻点中点 %2 %3</translation>
    </message>
</context>
<context>
    <name>mocap::ui::VideoView</name>
    <message>
        <location filename="../widgets/views/video_view.cpp" line="+37"/>
        <source>No reference video</source>
        <translation>无参考视频</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>No video at this frame</source>
        <translation>此帧没有视频</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>video frame %1 · %2 s</source>
        <translation>视频第 %1 帧 · %2 秒</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 · held</source>
        <translation>%1 · 已停住</translation>
    </message>
</context>
<context>
    <name>mocap::ui::VtkViewport</name>
    <message>
        <location filename="../widgets/views/vtk_viewport.cpp" line="+255"/>
        <source>No OpenGL context is available, so the 3D view cannot be shown.</source>
        <translation>没有可用的 OpenGL 上下文，无法显示 3D 视图。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The 3D view needs OpenGL 3.2; this display offers %1.%2.</source>
        <translation>3D 视图需要 OpenGL 3.2，当前显示仅提供 %1.%2。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The OpenGL context cannot be used, so the 3D view cannot be shown.</source>
        <translation>无法使用 OpenGL 上下文，因此无法显示 3D 视图。</translation>
    </message>
</context>
<context>
    <name>mocap::ui::WeightCurveView</name>
    <message>
        <location filename="../widgets/views/weight_curve_view.cpp" line="+121"/>
        <source>Solve the take to see its weights</source>
        <translation>求解拍摄后即可查看其权重</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Load a blendshape rig in the Blendshape Solve panel</source>
        <translation>请在混合形状求解面板中加载混合形状绑定模型</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Click a curve (or pick shapes in the panel) to select its shape</source>
        <translation>单击曲线（或在面板中选择形状）以选中其形状</translation>
    </message>
    <message>
        <location line="+48"/>
        <source>Weights through the map %1</source>
        <translation>经映射 %1 的权重</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Weights</source>
        <translation>权重</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Marker residual (%1)</source>
        <translation>标记点残差（%1）</translation>
    </message>
    <message>
        <location line="+89"/>
        <source>%1 · frame %2 · %3</source>
        <translation>%1 · 第 %2 帧 · %3</translation>
    </message>
</context>
<context>
    <name>mocap::ui::WeightEditActions</name>
    <message>
        <location filename="../widgets/actions/weight_edit_actions.cpp" line="+25"/>
        <source>Solve the take first.</source>
        <translation>请先求解拍摄。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Select the shapes to edit.</source>
        <translation>请选择要编辑的形状。</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Scale weights by %1</source>
        <translation>将权重缩放 %1 倍</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Zero weights</source>
        <translation>权重清零</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>The cut-off must lie between 0 and %1 Hz (half the frame rate).</source>
        <translation>截止频率必须在 0 到 %1 Hz 之间（帧率的一半）。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The take is too short to smooth.</source>
        <translation>拍摄太短，无法平滑。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Smooth weights (%1 Hz)</source>
        <translation>平滑权重（%1 Hz）</translation>
    </message>
</context>
</TS>
