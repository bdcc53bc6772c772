<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="pt_BR">
<context>
    <name>AnimationDialog</name>
    <message>
        <source>Rendering %1 frames…</source>
        <translation>Renderizando %1 quadros…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
</context>
<context>
    <name>DesktopEntry</name>
    <message>
        <source>Cannot open the scene</source>
        <translation>Não foi possível abrir a cena</translation>
    </message>
</context>
<context>
    <name>EdgeMarkers</name>
    <message>
        <source>%1 m away</source>
        <translation>a %1 m</translation>
    </message>
</context>
<context>
    <name>EquationsPanel</name>
    <message>
        <source>&lt;b&gt;Chaplygin sleigh&lt;/b&gt;: m = %1 kg, a = %2 m, b = %3 m (b² = a² + I/m, b is the radius of gyration about P)</source>
        <translation>&lt;b&gt;Trenó de Chaplygin&lt;/b&gt;: m = %1 kg, a = %2 m, b = %3 m (b² = a² + I/m, b é o raio de giração em relação a P)</translation>
    </message>
    <message>
        <source>&lt;b&gt;Rolling disk&lt;/b&gt; (App. A) as a sleigh: m_eff = m + I1/R² = %1 kg, b = R√(I2/(I1 + mR²)) = %2 √(%3/(%4 + %5·%2²)) = %6 m (A14); the contact point is under the centre, so a = 0</source>
        <translation>&lt;b&gt;Disco rolante&lt;/b&gt; (Apêndice A) como trenó: m_eff = m + I1/R² = %1 kg, b = R√(I2/(I1 + mR²)) = %2 √(%3/(%4 + %5·%2²)) = %6 m (A14); o ponto de contato fica sob o centro, logo a = 0</translation>
    </message>
    <message>
        <source>&lt;b&gt;Two-wheeled carriage&lt;/b&gt; (App. B) as a sleigh: m_eff = M + 2(m + I1/R²) = %1 kg, b = √(J/m_eff) = %2 m with J = I + 2I2 + 2a²(m + I1/R²) (B18); a = %3 m</source>
        <translation>&lt;b&gt;Carrinho de duas rodas&lt;/b&gt; (Apêndice B) como trenó: m_eff = M + 2(m + I1/R²) = %1 kg, b = √(J/m_eff) = %2 m com J = I + 2I2 + 2a²(m + I1/R²) (B18); a = %3 m</translation>
    </message>
    <message>
        <source>&lt;p&gt;t = &lt;b&gt;%1 s&lt;/b&gt;: s = %2 m, φ = %3 rad, κ = %4 1/m; %5&lt;/p&gt;</source>
        <translation>&lt;p&gt;t = &lt;b&gt;%1 s&lt;/b&gt;: s = %2 m, φ = %3 rad, κ = %4 1/m; %5&lt;/p&gt;</translation>
    </message>
    <message>
        <source>constant energy, v_T = %1 m/s</source>
        <translation>energia constante, v_T = %1 m/s</translation>
    </message>
    <message>
        <source>constant speed, v_s = %1 m/s (App. C)</source>
        <translation>velocidade constante, v_s = %1 m/s (Apêndice C)</translation>
    </message>
    <message>
        <source>Control angle</source>
        <translation>Ângulo de controle</translation>
    </message>
    <message>
        <source>%1 (corner: bκ → %2)</source>
        <translation>%1 (canto: bκ → %2)</translation>
    </message>
    <message>
        <source>at or after a cusp the sleigh backs up: Ψ leaves (0, π) continuously (docs/physics.md §3)</source>
        <translation>na cúspide ou depois dela o trenó anda de ré: Ψ sai de (0, π) continuamente (docs/physics.md §3)</translation>
    </message>
    <message>
        <source>pivot about P, docs/physics.md §3</source>
        <translation>pivô em torno de P, docs/physics.md §3</translation>
    </message>
    <message>
        <source>(45) tan Ψ = ρ/b on the branch Ψ ∈ (0, π) (erratum to (47))</source>
        <translation>(45) tan Ψ = ρ/b no ramo Ψ ∈ (0, π) (errata de (47))</translation>
    </message>
    <message>
        <source>Velocities and time law</source>
        <translation>Velocidades e lei horária</translation>
    </message>
    <message>
        <source>turning in place</source>
        <translation>girando no lugar</translation>
    </message>
    <message>
        <source>(35) with Ψ = 0 or π</source>
        <translation>(35) com Ψ = 0 ou π</translation>
    </message>
    <message>
        <source>(51); (52)–(53) corrected: 1/sin Ψ = √(1 + b²κ²)</source>
        <translation>(51); (52)–(53) corrigidas: 1/sin Ψ = √(1 + b²κ²)</translation>
    </message>
    <message>
        <source>(C15): the energy varies</source>
        <translation>(C15): a energia varia</translation>
    </message>
    <message>
        <source>t = s/v_s</source>
        <translation>t = s/v_s</translation>
    </message>
    <message>
        <source>(49) with ṡ² (erratum)</source>
        <translation>(49) com ṡ² (errata)</translation>
    </message>
    <message>
        <source>Driving angle and control multiplier</source>
        <translation>Ângulo de condução e multiplicador de controle</translation>
    </message>
    <message>
        <source>docs/physics.md §2</source>
        <translation>docs/physics.md §2</translation>
    </message>
    <message>
        <source>Forces on the body</source>
        <translation>Forças sobre o corpo</translation>
    </message>
    <message>
        <source>= λφ̇ (docs/physics.md §2)</source>
        <translation>= λφ̇ (docs/physics.md §2)</translation>
    </message>
    <message>
        <source>(69)–(70), at P</source>
        <translation>(69)–(70), em P</translation>
    </message>
    <message>
        <source>(69)–(70), at P; m_t = %1 kg translates with P (the disk&apos;s m, the carriage&apos;s M + 2m)</source>
        <translation>(69)–(70), em P; m_t = %1 kg translada com P (o m do disco, o M + 2m do carrinho)</translation>
    </message>
    <message>
        <source>= −λṡ: workless (S_c = Iφ̈, erratum to (66)–(68))</source>
        <translation>= −λṡ: não realiza trabalho (S_c = Iφ̈, errata de (66)–(68))</translation>
    </message>
    <message>
        <source>S_c = Iφ̈ (erratum to (66)–(68))</source>
        <translation>S_c = Iφ̈ (errata de (66)–(68))</translation>
    </message>
    <message>
        <source>0: the control does no work</source>
        <translation>0: o controle não realiza trabalho</translation>
    </message>
    <message>
        <source>dT/dt = m b²φ̇φ̈ (App. C)</source>
        <translation>dT/dt = m b²φ̇φ̈ (Apêndice C)</translation>
    </message>
    <message>
        <source>Free body (Lagrange–d&apos;Alembert ghost)</source>
        <translation>Corpo livre (fantasma de Lagrange–d&apos;Alembert)</translation>
    </message>
    <message>
        <source>(D12)–(D14) in closed form</source>
        <translation>(D12)–(D14) em forma fechada</translation>
    </message>
    <message>
        <source>V = √(ṡ₀² + b²φ̇₀²), k = aV/b², c = atanh(ṡ₀/V)</source>
        <translation>V = √(ṡ₀² + b²φ̇₀²), k = aV/b², c = atanh(ṡ₀/V)</translation>
    </message>
    <message>
        <source>Feedback law (closed loop)</source>
        <translation>Lei de realimentação (malha fechada)</translation>
    </message>
    <message>
        <source>&lt;p&gt;The feedback body against its closest path point: s_p = %1 m, κ = %2 1/m, κ′ = %3 1/m²; feedback rate P = %4 1/m&lt;/p&gt;</source>
        <translation>&lt;p&gt;O corpo realimentado diante do ponto mais próximo da trajetória: s_p = %1 m, κ = %2 1/m, κ′ = %3 1/m²; taxa de realimentação P = %4 1/m&lt;/p&gt;</translation>
    </message>
    <message>
        <source>lateral error, &gt; 0 to the left of the path</source>
        <translation>erro lateral, &gt; 0 à esquerda da trajetória</translation>
    </message>
    <message>
        <source>heading error</source>
        <translation>erro de rumo</translation>
    </message>
    <message>
        <source>= dz₂/ds_p</source>
        <translation>= dz₂/ds_p</translation>
    </message>
    <message>
        <source>= dz₃/ds_p</source>
        <translation>= dz₃/ds_p</translation>
    </message>
    <message>
        <source>a triple pole at −P in path length: e‴ + 3Pe″ + 3P²e′ + P³e = 0</source>
        <translation>um polo triplo em −P no comprimento da trajetória: e‴ + 3Pe″ + 3P²e′ + P³e = 0</translation>
    </message>
    <message>
        <source>dz₄/ds_p = Gκ_b′ + F, G = (1 − κe)² sec³θ</source>
        <translation>dz₄/ds_p = Gκ_b′ + F, G = (1 − κe)² sec³θ</translation>
    </message>
    <message>
        <source>; held at the limit |Ψ̇| ≤ %1 rad/s</source>
        <translation>; mantido no limite |Ψ̇| ≤ %1 rad/s</translation>
    </message>
    <message>
        <source>from κ_b = cot Ψ/b</source>
        <translation>de κ_b = cot Ψ/b</translation>
    </message>
    <message>
        <source>the controller&apos;s b_c = %1 m differs from the plant&apos;s</source>
        <translation>o b_c = %1 m do controlador difere do da planta</translation>
    </message>
    <message>
        <source>workless: the energy stays (m_eff/2)(ṡ² + b²φ̇²) = %1 J</source>
        <translation>sem trabalho: a energia fica (m_eff/2)(ṡ² + b²φ̇²) = %1 J</translation>
    </message>
    <message>
        <source>power f_sṡ + τφ̇</source>
        <translation>potência f_sṡ + τφ̇</translation>
    </message>
    <message>
        <source>at rest (the target is the start)</source>
        <translation>em repouso (o alvo é o início)</translation>
    </message>
    <message>
        <source>pivoting about P (Ψ ≡ 0 or π)</source>
        <translation>pivotando em torno de P (Ψ ≡ 0 ou π)</translation>
    </message>
    <message>
        <source>the straight line (Ψ ≡ ±π/2)</source>
        <translation>a linha reta (Ψ ≡ ±π/2)</translation>
    </message>
    <message>
        <source>libration (k &amp;lt; 1)</source>
        <translation>libração (k &amp;lt; 1)</translation>
    </message>
    <message>
        <source>rotation (k &amp;gt; 1)</source>
        <translation>rotação (k &amp;gt; 1)</translation>
    </message>
    <message>
        <source>separatrix (k = 1)</source>
        <translation>separatriz (k = 1)</translation>
    </message>
    <message>
        <source>Plan: motion %1 of %2, %3</source>
        <translation>Plano: movimento %1 de %2, %3</translation>
    </message>
    <message>
        <source>the pendulum&apos;s modulus, docs/physics.md §10</source>
        <translation>o módulo do pêndulo, docs/physics.md §10</translation>
    </message>
    <message>
        <source>Ψ(0) = atan2(ṡ, bφ̇) at the start</source>
        <translation>Ψ(0) = atan2(ṡ, bφ̇) no início</translation>
    </message>
    <message>
        <source>the one free constant: the control</source>
        <translation>a única constante livre: o controle</translation>
    </message>
    <message>
        <source>arrival, the least time (certified by the cut time)</source>
        <translation>chegada, o menor tempo (certificado pelo tempo de corte)</translation>
    </message>
    <message>
        <source>arrival</source>
        <translation>chegada</translation>
    </message>
    <message>
        <source>cut time</source>
        <translation>tempo de corte</translation>
    </message>
    <message>
        <source>optimal up to here: the first Maxwell time</source>
        <translation>ótimo até aqui: o primeiro tempo de Maxwell</translation>
    </message>
    <message>
        <source>along the motion now, t clamped to it</source>
        <translation>ao longo do movimento agora, t limitado a ele</translation>
    </message>
    <message>
        <source>along the motion now</source>
        <translation>ao longo do movimento agora</translation>
    </message>
</context>
<context>
    <name>MethodNames</name>
    <message>
        <source>Exact formula (the app&apos;s)</source>
        <translation>Fórmula exata (a do aplicativo)</translation>
    </message>
    <message>
        <source>Quadrature along the path (the app&apos;s)</source>
        <translation>Quadratura ao longo do caminho (a do aplicativo)</translation>
    </message>
    <message>
        <source>Adaptive quadrature (GSL)</source>
        <translation>Quadratura adaptativa (GSL)</translation>
    </message>
    <message>
        <source>Runge–Kutta 4 (GSL)</source>
        <translation>Runge–Kutta 4 (GSL)</translation>
    </message>
    <message>
        <source>Runge–Kutta Cash–Karp (GSL)</source>
        <translation>Runge–Kutta Cash–Karp (GSL)</translation>
    </message>
    <message>
        <source>Multistep Adams (GSL)</source>
        <translation>Adams de passo múltiplo (GSL)</translation>
    </message>
    <message>
        <source>Multistep BDF (GSL)</source>
        <translation>BDF de passo múltiplo (GSL)</translation>
    </message>
    <message>
        <source>Classical Runge–Kutta 4</source>
        <translation>Runge–Kutta 4 clássico</translation>
    </message>
    <message>
        <source>Runge–Kutta 4, energy kept</source>
        <translation>Runge–Kutta 4, energia mantida</translation>
    </message>
    <message>
        <source>Paper&apos;s open loop, Runge–Kutta 8 (GSL)</source>
        <translation>Malha aberta do artigo, Runge–Kutta 8 (GSL)</translation>
    </message>
    <message>
        <source>Paper&apos;s open loop, Runge–Kutta 4</source>
        <translation>Malha aberta do artigo, Runge–Kutta 4</translation>
    </message>
    <message>
        <source>Time along the path: exact formula</source>
        <translation>Tempo ao longo do caminho: fórmula exata</translation>
    </message>
    <message>
        <source>Time along the path: quadrature</source>
        <translation>Tempo ao longo do caminho: quadratura</translation>
    </message>
    <message>
        <source>; ghost and vakonomic body: formulas, no time stepping</source>
        <translation>; fantasma e corpo vakonômico: fórmulas, sem passos no tempo</translation>
    </message>
    <message>
        <source>; pushed bodies: Runge–Kutta 8 integration</source>
        <translation>; corpos empurrados: integração Runge–Kutta 8</translation>
    </message>
    <message>
        <source>path: %1
time law: %2
s(t): %3
control: %4
free velocities: %5
free position: %6
vakonomic body: %7</source>
        <translation>caminho: %1
lei horária: %2
s(t): %3
controle: %4
velocidades livres: %5
posição livre: %6
corpo vakonômico: %7</translation>
    </message>
    <message>
        <source>
open loop: %1
feedback: %2</source>
        <translation>
malha aberta: %1
realimentação: %2</translation>
    </message>
    <message>
        <source>Runge–Kutta–Fehlberg 4(5) (GSL)</source>
        <translation>Runge–Kutta–Fehlberg 4(5) (GSL)</translation>
    </message>
    <message>
        <source>Runge–Kutta Prince–Dormand 8 (GSL)</source>
        <translation>Runge–Kutta Prince–Dormand 8 (GSL)</translation>
    </message>
    <message>
        <source>Exact formula</source>
        <translation>Fórmula exata</translation>
    </message>
    <message>
        <source>Path quadrature</source>
        <translation>Quadratura no caminho</translation>
    </message>
    <message>
        <source>QAG (GSL)</source>
        <translation>QAG (GSL)</translation>
    </message>
    <message>
        <source>RK4 (GSL)</source>
        <translation>RK4 (GSL)</translation>
    </message>
    <message>
        <source>RKF45 (GSL)</source>
        <translation>RKF45 (GSL)</translation>
    </message>
    <message>
        <source>Cash–Karp (GSL)</source>
        <translation>Cash–Karp (GSL)</translation>
    </message>
    <message>
        <source>RK8PD (GSL)</source>
        <translation>RK8PD (GSL)</translation>
    </message>
    <message>
        <source>Adams (GSL)</source>
        <translation>Adams (GSL)</translation>
    </message>
    <message>
        <source>BDF (GSL)</source>
        <translation>BDF (GSL)</translation>
    </message>
    <message>
        <source>RK4</source>
        <translation>RK4</translation>
    </message>
    <message>
        <source>RK4, energy kept</source>
        <translation>RK4, energia mantida</translation>
    </message>
    <message>
        <source>Open loop, RK8PD</source>
        <translation>Malha aberta, RK8PD</translation>
    </message>
    <message>
        <source>Open loop, RK4</source>
        <translation>Malha aberta, RK4</translation>
    </message>
</context>
<context>
    <name>ModelReport</name>
    <message>
        <source>closed form (t = s/v_s)</source>
        <translation>forma fechada (t = s/v_s)</translation>
    </message>
    <message>
        <source>closed form</source>
        <translation>forma fechada</translation>
    </message>
    <message>
        <source>Newton on s(u)</source>
        <translation>Newton em s(u)</translation>
    </message>
    <message>
        <source>closed form (constant curvature: t = s sqrt(1 + b^2 kappa^2)/v_T)</source>
        <translation>forma fechada (curvatura constante: t = s sqrt(1 + b^2 kappa^2)/v_T)</translation>
    </message>
    <message>
        <source>quadrature (Gauss-Legendre of sqrt(1 + b^2 kappa^2)/v_T ds)</source>
        <translation>quadratura (Gauss-Legendre de sqrt(1 + b^2 kappa^2)/v_T ds)</translation>
    </message>
    <message>
        <source>Newton on t(s) with the exact dt/ds</source>
        <translation>Newton em t(s) com o dt/ds exato</translation>
    </message>
    <message>
        <source>quadrature (Gauss-Legendre of sqrt(1 + b^2 kappa^2)/v_T ds) at the panel ends; inside a panel the integral of the Chebyshev interpolant of dt/du at the panel&apos;s degree, certified to 1e-13 of the panel&apos;s time on first use (exact Gauss-Legendre where it fails)</source>
        <translation>quadratura (Gauss-Legendre de sqrt(1 + b^2 kappa^2)/v_T ds) nas extremidades dos painéis; dentro de um painel, a integral do interpolante de Chebyshev de dt/du no grau do painel, certificada a 1e-13 do tempo do painel no primeiro uso (Gauss-Legendre exato onde falha)</translation>
    </message>
    <message>
        <source>Newton on the interpolated t(u) from a quintic Hermite start</source>
        <translation>Newton no t(u) interpolado, a partir de um chute inicial de Hermite quíntico</translation>
    </message>
    <message>
        <source>closed form in kappa, dkappa/ds and phi (Psi = atan2(1, b kappa))</source>
        <translation>forma fechada em kappa, dkappa/ds e phi (Psi = atan2(1, b kappa))</translation>
    </message>
    <message>
        <source>closed form (at rest)</source>
        <translation>forma fechada (em repouso)</translation>
    </message>
    <message>
        <source>closed form (straight line, phidot0 = 0)</source>
        <translation>forma fechada (reta, phidot0 = 0)</translation>
    </message>
    <message>
        <source>closed form (uniform circle, a = 0)</source>
        <translation>forma fechada (círculo uniforme, a = 0)</translation>
    </message>
    <message>
        <source>closed form (sdot = V tanh, phidot = (V/b) sech); inside the tabulated horizon from degree-16 interpolants of it, certified to 1e-15 V and 1e-15 V/b</source>
        <translation>forma fechada (sdot = V tanh, phidot = (V/b) sech); dentro do horizonte tabulado, por interpolantes de grau 16 dela, certificados a 1e-15 V e 1e-15 V/b</translation>
    </message>
    <message>
        <source>quadrature: per panel the integral of the degree-16 interpolant of sdot e^(i phi), certified to 1e-15 of the panel&apos;s displacement (Gauss-Legendre where not); straight-line tail</source>
        <translation>quadratura: em cada painel, a integral do interpolante de grau 16 de sdot e^(i phi), certificada a 1e-15 do deslocamento do painel (Gauss-Legendre onde não); cauda em linha reta</translation>
    </message>
    <message>
        <source>closed form (straight line: Psi = pi/2, Psidot = 0, an unstable equilibrium)</source>
        <translation>forma fechada (reta: Psi = pi/2, Psidot = 0, um equilíbrio instável)</translation>
    </message>
    <message>
        <source>closed form (separatrix k = 1: Psi = gd(tau), position in tanh and sech)</source>
        <translation>forma fechada (separatriz k = 1: Psi = gd(tau), posição em tanh e sech)</translation>
    </message>
</context>
<context>
    <name>PlotFigures</name>
    <message>
        <source>controlled Ψ</source>
        <translation>Ψ controlado</translation>
    </message>
    <message>
        <source>free Ψ</source>
        <translation>Ψ livre</translation>
    </message>
    <message>
        <source>controlled χ</source>
        <translation>χ controlado</translation>
    </message>
    <message>
        <source>free χ (constant)</source>
        <translation>χ livre (constante)</translation>
    </message>
    <message>
        <source>controlled T</source>
        <translation>T controlado</translation>
    </message>
    <message>
        <source>free T</source>
        <translation>T livre</translation>
    </message>
    <message>
        <source>kinetic energy T [J]</source>
        <translation>energia cinética T [J]</translation>
    </message>
    <message>
        <source>prescribed path</source>
        <translation>caminho prescrito</translation>
    </message>
    <message>
        <source>controlled body (P)</source>
        <translation>corpo controlado (P)</translation>
    </message>
    <message>
        <source>free body (P)</source>
        <translation>corpo livre (P)</translation>
    </message>
    <message>
        <source>path</source>
        <translation>caminho</translation>
    </message>
    <message>
        <source>tracked y(x)</source>
        <translation>y(x) seguido</translation>
    </message>
    <message>
        <source>Control angle Ψ(t)</source>
        <translation>Ângulo de controle Ψ(t)</translation>
    </message>
    <message>
        <source>Driving angle χ(t)</source>
        <translation>Ângulo de condução χ(t)</translation>
    </message>
    <message>
        <source>Control multiplier λ(t)</source>
        <translation>Multiplicador de controle λ(t)</translation>
    </message>
    <message>
        <source>Kinetic energy T(t)</source>
        <translation>Energia cinética T(t)</translation>
    </message>
    <message>
        <source>Trajectories of the knife point P</source>
        <translation>Trajetórias do ponto da lâmina P</translation>
    </message>
    <message>
        <source>s(t), x(t), y(t) and y(x), as in the paper&apos;s Figs. 2-3</source>
        <translation>s(t), x(t), y(t) e y(x), como nas Figs. 2-3 do artigo</translation>
    </message>
    <message>
        <source>vakonomic Ψ</source>
        <translation>Ψ vakonômico</translation>
    </message>
    <message>
        <source>free</source>
        <translation>livre</translation>
    </message>
    <message>
        <source>vakonomic</source>
        <translation>vakonômico</translation>
    </message>
    <message>
        <source>vakonomic χ</source>
        <translation>χ vakonômico</translation>
    </message>
    <message>
        <source>vakonomic λ (eq. 21)</source>
        <translation>λ vakonômico (eq. 21)</translation>
    </message>
    <message>
        <source>vakonomic T</source>
        <translation>T vakonômico</translation>
    </message>
    <message>
        <source>vakonomic body (P)</source>
        <translation>corpo vakonômico (P)</translation>
    </message>
    <message>
        <source>open loop e</source>
        <translation>malha aberta e</translation>
    </message>
    <message>
        <source>feedback e</source>
        <translation>realimentação e</translation>
    </message>
    <message>
        <source>lateral error e [m]</source>
        <translation>erro lateral e [m]</translation>
    </message>
    <message>
        <source>open loop θ</source>
        <translation>malha aberta θ</translation>
    </message>
    <message>
        <source>feedback θ</source>
        <translation>realimentação θ</translation>
    </message>
    <message>
        <source>heading error θ [rad]</source>
        <translation>erro de rumo θ [rad]</translation>
    </message>
    <message>
        <source>Pushed bodies: lateral error e(t) and heading error θ(t)</source>
        <translation>Corpos empurrados: erro lateral e(t) e erro de rumo θ(t)</translation>
    </message>
    <message>
        <source>planned Ψ (vakonomic)</source>
        <translation>Ψ planejado (vakonômico)</translation>
    </message>
    <message>
        <source>planned χ (vakonomic)</source>
        <translation>χ planejado (vakonômico)</translation>
    </message>
    <message>
        <source>planned λ (eq. 21)</source>
        <translation>λ planejado (eq. 21)</translation>
    </message>
    <message>
        <source>planned T (vakonomic)</source>
        <translation>T planejado (vakonômico)</translation>
    </message>
</context>
<context>
    <name>PlotSeries</name>
    <message>
        <source>sleigh</source>
        <translation>trenó</translation>
    </message>
    <message>
        <source>disk</source>
        <translation>disco</translation>
    </message>
    <message>
        <source>carriage</source>
        <translation>carrinho</translation>
    </message>
    <message>
        <source>constant energy, v_T = %1 m/s</source>
        <translation>energia constante, v_T = %1 m/s</translation>
    </message>
    <message>
        <source>constant speed, v_s = %1 m/s</source>
        <translation>velocidade constante, v_s = %1 m/s</translation>
    </message>
    <message>
        <source>preset %1 — </source>
        <translation>predefinição %1 — </translation>
    </message>
    <message>
        <source>planned motion from %1 to %2 in t = %3 s, Ψ(0) = %4, k = %5
%6: m_eff = %7 kg, a = %8 m, b = %9 m, v_T = %10 m/s</source>
        <translation>movimento planejado de %1 a %2 em t = %3 s, Ψ(0) = %4, k = %5
%6: m_eff = %7 kg, a = %8 m, b = %9 m, v_T = %10 m/s</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>pin %1: %2</source>
        <translation>execução %1: %2</translation>
    </message>
    <message>
        <source>Export this plot…</source>
        <translation>Exportar este gráfico…</translation>
    </message>
    <message>
        <source>Fit all curves</source>
        <translation>Enquadrar todas as curvas</translation>
    </message>
    <message>
        <source>Show the free and vakonomic curves whole instead of clipping them at the frame</source>
        <translation>Mostrar as curvas livre e vakonômica inteiras em vez de cortá-las na moldura</translation>
    </message>
    <message>
        <source>Export the plot</source>
        <translation>Exportar o gráfico</translation>
    </message>
    <message>
        <source>PNG image (*.png);;PDF (*.pdf);;SVG (*.svg)</source>
        <translation>Imagem PNG (*.png);;PDF (*.pdf);;SVG (*.svg)</translation>
    </message>
</context>
<context>
    <name>SceneFiles</name>
    <message>
        <source>cannot open &apos;%1&apos;</source>
        <translation>não é possível abrir &apos;%1&apos;</translation>
    </message>
    <message>
        <source>no such file</source>
        <translation>arquivo inexistente</translation>
    </message>
    <message>
        <source>it is a directory, not a scene file</source>
        <translation>é um diretório, não um arquivo de cena</translation>
    </message>
</context>
<context>
    <name>SceneTexts</name>
    <message>
        <source>Feedback too aggressive for its actuator</source>
        <translation>Realimentação agressiva demais para o seu atuador</translation>
    </message>
    <message>
        <source>The feedback asks for a triple pole at P = 2.5 per metre, but the actuator turns the control angle at most 0.4 rad/s (|Ψ̇| ≤ 0.4). The law saturates while the body is far off, arrives at the line too fast and overshoots it by 0.2 m before settling; the same law without the bound approaches from one side and never crosses. At P = 3 with the same bound the overshoot grows until the heading error reaches π/2 and the chained form no longer exists: the app refuses that scene and says when it happens (docs/physics.md §9).</source>
        <translation>A realimentação pede um polo triplo em P = 2,5 por metro, mas o atuador gira o ângulo de controle a no máximo 0,4 rad/s (|Ψ̇| ≤ 0,4). A lei satura enquanto o corpo está longe, chega à reta rápido demais e a ultrapassa em 0,2 m antes de se acomodar; a mesma lei sem o limite se aproxima por um só lado e nunca cruza a reta. Com P = 3 e o mesmo limite, a ultrapassagem cresce até o erro de orientação chegar a π/2 e a forma encadeada deixar de existir: o programa recusa essa cena e diz quando isso acontece (docs/physics.md §9).</translation>
    </message>
    <message>
        <source>A corner in constant-speed mode: cannot turn</source>
        <translation>Um canto no modo de velocidade constante: não consegue girar</translation>
    </message>
    <message>
        <source>With ṡ = v_s fixed (App. C) the kinetic energy is (m/2) v_s² (1 + b²κ²), which is infinite at a corner. No finite control turns the sleigh there; the app refuses the scene and names the corner. Smooth the corners or use constant energy.</source>
        <translation>Com ṡ = v_s fixo (Apêndice C), a energia cinética é (m/2) v_s² (1 + b²κ²), infinita num canto. Nenhum controle finito faz o trenó girar ali; o programa recusa a cena e aponta o canto. Suavize os cantos ou use energia constante.</translation>
    </message>
    <message>
        <source>A corner in constant-energy mode: pivot in place</source>
        <translation>Um canto no modo de energia constante: pivô no lugar</translation>
    </message>
    <message>
        <source>At a corner of a drawn polyline the curvature is a delta function: Ψ goes to 0 (left) or π (right), ṡ = 0 and |φ̇| = v_T/b. The sleigh stops and turns about the knife point for b |Δφ|/v_T seconds, driven by an impulsive but workless control.</source>
        <translation>Num canto de uma poligonal desenhada, a curvatura é uma função delta: Ψ vai a 0 (à esquerda) ou a π (à direita), ṡ = 0 e |φ̇| = v_T/b. O trenó para e gira em torno do ponto da lâmina durante b |Δφ|/v_T segundos, movido por um controle impulsivo que não realiza trabalho.</translation>
    </message>
    <message>
        <source>A cusp: the sleigh backs up</source>
        <translation>Uma cúspide: o trenó anda de ré</translation>
    </message>
    <message>
        <source>On x = u², y = u³ the velocity r′(u) vanishes at u = 0 and the direction of travel reverses, but the knife&apos;s heading, the tangent line, turns smoothly through the cusp. In constant-energy mode the sleigh slows to ṡ = 0 while it keeps turning at |φ̇| = v_T/b, then backs up: ṡ changes sign, Ψ = atan2(ṡ, b φ̇) leaves (0, π) continuously (here through 0 to negative values), and the time to pass, (1/v_T) ∫ √(ds² + b² dφ²), is finite although the curvature is infinite at the cusp. The paper&apos;s forward branch Ψ = atan2(1, bκ) cannot do this. Constant-speed mode refuses the path and names the cusp: ṡ would have to jump from +v_s to −v_s.</source>
        <translation>Em x = u², y = u³ a velocidade r′(u) se anula em u = 0 e o sentido do percurso se inverte, mas a direção da lâmina, a reta tangente, gira suavemente ao passar pela cúspide. No modo de energia constante o trenó desacelera até ṡ = 0 enquanto continua girando com |φ̇| = v_T/b, e então anda de ré: ṡ troca de sinal, Ψ = atan2(ṡ, b φ̇) sai de (0, π) continuamente (aqui passando por 0 para valores negativos), e o tempo de passagem, (1/v_T) ∫ √(ds² + b² dφ²), é finito, embora a curvatura seja infinita na cúspide. O ramo progressivo do artigo, Ψ = atan2(1, bκ), não consegue fazer isso. O modo de velocidade constante recusa o caminho e aponta a cúspide: ṡ teria de saltar de +v_s para −v_s.</translation>
    </message>
    <message>
        <source>Very high curvature, bκ = 1000</source>
        <translation>Curvatura muito alta, bκ = 1000</translation>
    </message>
    <message>
        <source>A sinusoid a thousand times smaller than the sleigh: bκ reaches 1000, the sleigh almost only turns, and √(1 + b²κ²) has a near-kink at every inflection. Explicit ODE steppers in t need steps a thousand times smaller than on the paper&apos;s sinusoid; the app&apos;s quadrature on the adaptive path table stays exact.</source>
        <translation>Uma senoide mil vezes menor que o trenó: bκ chega a 1000, o trenó quase só gira, e √(1 + b²κ²) tem quase uma quina em cada inflexão. Integradores explícitos de EDO em t precisam de passos mil vezes menores que na senoide do artigo; a quadratura do programa sobre a tabela adaptativa do caminho continua exata.</translation>
    </message>
    <message>
        <source>A long horizon: t = 5000 s</source>
        <translation>Um horizonte longo: t = 5000 s</translation>
    </message>
    <message>
        <source>Six hundred laps of a unit circle, 5000 s. The free sleigh&apos;s φ̇ decays like sech and would reach subnormal numbers, slowing an ODE solver several times; the closed form switches to a straight line once the heading is constant to 10⁻¹⁷, so every time costs the same.</source>
        <translation>Seiscentas voltas num círculo unitário, 5000 s. O φ̇ do trenó livre decai como sech e chegaria a números subnormais, deixando um resolvedor de EDO várias vezes mais lento; a forma fechada passa a uma reta assim que a orientação fica constante a 10⁻¹⁷, de modo que todo instante custa o mesmo.</translation>
    </message>
    <message>
        <source>Open-loop integration of (36)-(37) drifts off the path</source>
        <translation>A integração em malha aberta de (36)-(37) se afasta do caminho</translation>
    </message>
    <message>
        <source>The paper integrates ẋ = v_T sin Ψ cos φ, ẏ = v_T sin Ψ sin φ in time (Fig. 3). Nothing pulls the integrated body back to the path, so every error in φ accumulates and the body drifts away; the method lab shows it. The app integrates along the path instead and is on the path by construction.</source>
        <translation>O artigo integra ẋ = v_T sin Ψ cos φ, ẏ = v_T sin Ψ sin φ no tempo (Fig. 3). Nada traz o corpo integrado de volta ao caminho, então todo erro em φ se acumula e o corpo se afasta; o laboratório de métodos mostra isso. O programa integra ao longo do caminho e, por construção, fica sobre ele.</translation>
    </message>
    <message>
        <source>sinusoid</source>
        <translation>senoide</translation>
    </message>
    <message>
        <source>The paper&apos;s printed branch reverses at inflections</source>
        <translation>O ramo impresso no artigo se inverte nas inflexões</translation>
    </message>
    <message>
        <source>The paper prints tan Ψ = ρ/b with Ψ in (−π/2, π/2). On y = −sin x the curvature changes sign at every multiple of π; with the printed branch Ψ jumps from +π/2 to −π/2 there, ṡ = v_T sin Ψ becomes negative and the sleigh would reverse along a path it is meant to follow forwards. Chaplygin Lab takes Ψ = atan2(1, bκ) in (0, π): Ψ passes π/2 smoothly and ṡ stays positive.</source>
        <translation>O artigo imprime tan Ψ = ρ/b com Ψ em (−π/2, π/2). Em y = −sin x a curvatura troca de sinal em todo múltiplo de π; com o ramo impresso, Ψ salta de +π/2 para −π/2 ali, ṡ = v_T sin Ψ fica negativo e o trenó voltaria de ré por um caminho que deveria seguir para a frente. O Chaplygin Lab usa Ψ = atan2(1, bκ) em (0, π): Ψ passa suavemente por π/2 e ṡ continua positivo.</translation>
    </message>
    <message>
        <source>Pushed off the path: open loop drifts, feedback returns</source>
        <translation>Empurrado para fora do caminho: a malha aberta deriva, a realimentação volta</translation>
    </message>
    <message>
        <source>At t = 3 s the sleigh is knocked sideways by 0.15 m and its control angle Ψ jumps by 0.4 rad. The open-loop body keeps applying the paper&apos;s λ(t), planned for the unperturbed motion: χ − χ_nominal stays at the push&apos;s 0.4 rad for ever (χ̇ = λ/(m b) does not see the state), so its heading settles off the path&apos;s and it drifts, 5.5 m away by the end. The feedback body gets the same push and the chained-form law (docs/physics.md §9) steers it back: its lateral error decays like e^(−Ps) with a triple pole at P = 1 per metre of path, below 10⁻⁴ m by the end. Both bodies keep the energy exactly: the correction is workless, it only turns the velocity.</source>
        <translation>Em t = 3 s o trenó é empurrado 0,15 m para o lado e o seu ângulo de controle Ψ salta 0,4 rad. O corpo em malha aberta continua aplicando o λ(t) do artigo, planejado para o movimento sem perturbação: χ − χ_nominal fica para sempre nos 0,4 rad do empurrão (χ̇ = λ/(m b) não enxerga o estado), então a sua orientação se acomoda fora da do caminho e ele deriva, a 5,5 m de distância no final. O corpo com realimentação recebe o mesmo empurrão e a lei na forma encadeada (docs/physics.md §9) o traz de volta: o seu erro lateral decai como e^(−Ps), com um polo triplo em P = 1 por metro de caminho, abaixo de 10⁻⁴ m no final. Os dois corpos conservam exatamente a energia: a correção não realiza trabalho, só gira a velocidade.</translation>
    </message>
    <message>
        <source>The genuine vakonomic system leaves the circle</source>
        <translation>O sistema vakonômico genuíno deixa o círculo</translation>
    </message>
    <message>
        <source>If λ obeys its own equation (21) instead of being an external control, only λ(0) is free. Started on the circle with the tracking λ, the genuine vakonomic sleigh leaves the circle within seconds: the paper&apos;s tracking is a control-input system, not the vakonomic one (docs/physics.md §2).</source>
        <translation>Se λ obedece à sua própria equação (21) em vez de ser um controle externo, só λ(0) é livre. Partindo do círculo com o λ do rastreamento, o trenó vakonômico genuíno deixa o círculo em poucos segundos: o rastreamento do artigo é um sistema com entrada de controle, não o sistema vakonômico (docs/physics.md §2).</translation>
    </message>
    <message>
        <source>circle</source>
        <translation>círculo</translation>
    </message>
    <message>
        <source>The controller&apos;s b is wrong</source>
        <translation>O b do controlador está errado</translation>
    </message>
    <message>
        <source>The plant&apos;s radius of gyration is b = 1 m, the controller believes 0.7 m. It measures the body&apos;s curvature φ̇/ṡ correctly but turns the curvature rate it wants into λ with its own b, so the body turns at a rate g = (b_c/b)² (1 + b²κ_b²)/(1 + b_c²κ_b²) times the one asked for, the feedforward included. On the sinusoid the lateral error never settles: it stays about 0.3 m. On a straight line the loop becomes s³ + 3gP s² + 3gP² s + gP³, stable only for g &gt; 1/9, that is b_c &gt; b/3 (docs/physics.md §9); a controller that overestimates b is only slower to converge.</source>
        <translation>O raio de giração da planta é b = 1 m, mas o controlador acredita em 0,7 m. Ele mede corretamente a curvatura do corpo, φ̇/ṡ, mas converte em λ a taxa de curvatura que deseja usando o seu próprio b, de modo que o corpo gira a uma taxa g = (b_c/b)² (1 + b²κ_b²)/(1 + b_c²κ_b²) vezes a pedida, incluída a antecipação (feedforward). Na senoide o erro lateral nunca se acomoda: fica em torno de 0,3 m. Numa reta a malha se torna s³ + 3gP s² + 3gP² s + gP³, estável só para g &gt; 1/9, isto é, b_c &gt; b/3 (docs/physics.md §9); um controlador que superestima b apenas converge mais devagar.</translation>
    </message>
    <message>
        <source>catenary</source>
        <translation>catenária</translation>
    </message>
    <message>
        <source>Catenary with x₀ = 1, arc length 0 to 5 (eqs. 97–107, Fig. 2): turns clockwise, Ψ in (π/2, π).</source>
        <translation>Catenária com x₀ = 1, comprimento de arco de 0 a 5 (eqs. 97–107, Fig. 2): gira no sentido horário, Ψ em (π/2, π).</translation>
    </message>
    <message>
        <source>Circle of radius 2 from (2, 0), counter-clockwise (eqs. 82–96): period 2π √(b² + R²)/v_T.</source>
        <translation>Círculo de raio 2 a partir de (2, 0), no sentido anti-horário (eqs. 82–96): período 2π √(b² + R²)/v_T.</translation>
    </message>
    <message>
        <source>line</source>
        <translation>reta</translation>
    </message>
    <message>
        <source>Straight line y = 0.5 x + 1 (paper eqs. 72–81): Ψ = π/2, χ constant, λ = 0.</source>
        <translation>Reta y = 0,5 x + 1 (eqs. 72–81 do artigo): Ψ = π/2, χ constante, λ = 0.</translation>
    </message>
    <message>
        <source>Sinusoid y = −sin x over two periods (eqs. 108–113, Fig. 3): Ψ passes π/2 at inflections.</source>
        <translation>Senoide y = −sin x ao longo de dois períodos (eqs. 108–113, Fig. 3): Ψ passa por π/2 nas inflexões.</translation>
    </message>
    <message>
        <source>Park sideways by b: two mirror optima</source>
        <translation>Estacionar de lado por b: dois ótimos espelhados</translation>
    </message>
    <message>
        <source>Pose to pose (docs/physics.md §10): the sleigh is moved sideways by b, from (0, 0, 0) to (0, 1, 0) with the same heading. The knife forbids the direct move, so the fastest manoeuvre drives forward, turns, backs up through a cusp and straightens again, in t = 3.3404 b/v_T. This scene tracks the forward-first optimum (Ψ0 = 2.0344, bΨ̇0/v_T = 1.4929); its mirror image, backing up first (Ψ0 = −1.1071), arrives at the same time: the target lies on the Maxwell set, where two minimisers tie and both arrive exactly at their cut time. The controlled body tracking this knife track and the genuine vakonomic body coincide: on a geodesic&apos;s track the paper&apos;s tracking is genuinely vakonomic. The Plan tool draws both optima.</source>
        <translation>De pose a pose (docs/physics.md §10): o trenó é deslocado de lado por b, de (0, 0, 0) a (0, 1, 0) com a mesma orientação. A faca proíbe o movimento direto; a manobra mais rápida avança, vira, dá ré por uma cúspide e se endireita, em t = 3,3404 b/v_T. Esta cena segue o ótimo que começa para a frente (Ψ0 = 2,0344, bΨ̇0/v_T = 1,4929); sua imagem espelhada, que começa de ré (Ψ0 = −1,1071), chega no mesmo instante: o alvo está no conjunto de Maxwell, onde dois minimizadores empatam e ambos chegam exatamente no tempo de corte. O corpo controlado que segue este rastro e o corpo vakonômico genuíno coincidem: no rastro de uma geodésica o rastreamento do artigo é genuinamente vakonômico. A ferramenta Planejar desenha os dois ótimos.</translation>
    </message>
    <message>
        <source>A geodesic past its cut time</source>
        <translation>Uma geodésica além do seu tempo de corte</translation>
    </message>
    <message>
        <source>Pose to pose (docs/physics.md §10): from (0, 0, 0) to (2, 0, 0), straight ahead. The straight line gets there in t = 2 b/v_T, and it is the optimum. This scene tracks another genuine vakonomic motion to the same target: a libration (k = 0.556, Ψ0 = 0.5896, Ψ̇0 = 0) that swings forward and back through two cusps and arrives at t = 6.8771 b/v_T, twice its cut time 3.4385 b/v_T. It does reach the target (the controlled body ends on it to 1e-14), and it is a geodesic, but past its cut time it is no longer a shortest way: the straight line, 3.4 times shorter, is. Its mirror image (Ψ0 = 2.5520) arrives at the same time. Shooting alone can return such a motion; the planner certifies the optimum with the cut time. The Plan tool draws the straight line beside it.</source>
        <translation>De pose a pose (docs/physics.md §10): de (0, 0, 0) a (2, 0, 0), em linha reta. A reta chega em t = 2 b/v_T e é o ótimo. Esta cena segue outro movimento vakonômico genuíno para o mesmo alvo: uma libração (k = 0,556, Ψ0 = 0,5896, Ψ̇0 = 0) que oscila para a frente e para trás por duas cúspides e chega em t = 6,8771 b/v_T, o dobro do seu tempo de corte 3,4385 b/v_T. Ela alcança o alvo (o corpo controlado termina nele a menos de 1e-14) e é uma geodésica, mas depois do tempo de corte deixa de ser um caminho mais curto: a reta, 3,4 vezes mais curta, é. Sua imagem espelhada (Ψ0 = 2,5520) chega no mesmo instante. Um método de tiro sozinho pode devolver um movimento assim; o planejador certifica o ótimo pelo tempo de corte. A ferramenta Planejar desenha a reta ao lado.</translation>
    </message>
    <message>
        <source>Pivot by π: the Maxwell point</source>
        <translation>Girar de π: o ponto de Maxwell</translation>
    </message>
    <message>
        <source>Pose to pose (docs/physics.md §10): the target is the start turned by π, (0, 0, π). The least time is π b/v_T, spent pivoting in place about the knife point with Ψ ≡ 0 (turning left), which is what this scene tracks. Turning right (Ψ ≡ π) takes exactly as long: the two pivots tie, the target lies on the Maxwell set, and π b/v_T is the pivot&apos;s cut time, so every turn by less than π is optimal and every turn by more is not (the other way round is shorter). The controlled body&apos;s λ here is that of the genuine vakonomic body: λ = −m a φ̇ while pivoting. The Plan tool draws both pivots.</source>
        <translation>De pose a pose (docs/physics.md §10): o alvo é o início girado de π, (0, 0, π). O menor tempo é π b/v_T, girando no lugar em torno do ponto da faca com Ψ ≡ 0 (para a esquerda), que é o que esta cena segue. Girar para a direita (Ψ ≡ π) leva exatamente o mesmo tempo: os dois giros empatam, o alvo está no conjunto de Maxwell, e π b/v_T é o tempo de corte do giro, de modo que todo giro de menos de π é ótimo e todo giro de mais não é (pelo outro lado é mais curto). O λ do corpo controlado é aqui o do corpo vakonômico genuíno: λ = −m a φ̇ durante o giro. A ferramenta Planejar desenha os dois giros.</translation>
    </message>
</context>
<context>
    <name>SweepPlot</name>
    <message>
        <source>Sweep of %1: %2</source>
        <translation>Varredura de %1: %2</translation>
    </message>
</context>
<context>
    <name>SweepQuantity</name>
    <message>
        <source>duration [s]</source>
        <translation>duração [s]</translation>
    </message>
    <message>
        <source>max |λ| [kg m/s]</source>
        <translation>máx |λ| [kg m/s]</translation>
    </message>
    <message>
        <source>max |τ| [N m]</source>
        <translation>máx |τ| [N m]</translation>
    </message>
    <message>
        <source>max |N| [N]</source>
        <translation>máx |N| [N]</translation>
    </message>
    <message>
        <source>max |power| [W]</source>
        <translation>máx |potência| [W]</translation>
    </message>
    <message>
        <source>final separation from the free body [m]</source>
        <translation>separação final do corpo livre [m]</translation>
    </message>
</context>
<context>
    <name>SystemParameters</name>
    <message>
        <source>mass m</source>
        <translation>massa m</translation>
    </message>
    <message>
        <source>The sleigh&apos;s mass</source>
        <translation>A massa do trenó</translation>
    </message>
    <message>
        <source>CM offset a</source>
        <translation>deslocamento a do CM</translation>
    </message>
    <message>
        <source>How far the centre of mass lies ahead of the knife&apos;s contact point P (negative: behind it)</source>
        <translation>A que distância o centro de massa fica à frente do ponto de contato P da lâmina (negativo: atrás dele)</translation>
    </message>
    <message>
        <source>moment of inertia I about the CM</source>
        <translation>momento de inércia I em relação ao CM</translation>
    </message>
    <message>
        <source>The moment of inertia about the centre of mass; b² = a² + I/m</source>
        <translation>O momento de inércia em relação ao centro de massa; b² = a² + I/m</translation>
    </message>
    <message>
        <source>gyration radius b about P</source>
        <translation>raio de giração b em relação a P</translation>
    </message>
    <message>
        <source>The radius of gyration about the contact point P; b² = a² + I/m, so b ≥ |a|</source>
        <translation>O raio de giração em relação ao ponto de contato P; b² = a² + I/m, logo b ≥ |a|</translation>
    </message>
    <message>
        <source>The disk&apos;s mass</source>
        <translation>A massa do disco</translation>
    </message>
    <message>
        <source>wheel radius R</source>
        <translation>raio da roda R</translation>
    </message>
    <message>
        <source>The disk&apos;s radius</source>
        <translation>O raio do disco</translation>
    </message>
    <message>
        <source>wheel inertia I1 about its axle</source>
        <translation>inércia da roda I1 em relação ao seu eixo</translation>
    </message>
    <message>
        <source>The moment of inertia about the axle (a uniform disk: m R²/2)</source>
        <translation>O momento de inércia em relação ao eixo (um disco uniforme: m R²/2)</translation>
    </message>
    <message>
        <source>wheel inertia I2 about a diameter</source>
        <translation>inércia da roda I2 em relação a um diâmetro</translation>
    </message>
    <message>
        <source>The moment of inertia about a vertical diameter (a uniform disk: m R²/4)</source>
        <translation>O momento de inércia em relação a um diâmetro vertical (um disco uniforme: m R²/4)</translation>
    </message>
    <message>
        <source>The radius of each wheel</source>
        <translation>O raio de cada roda</translation>
    </message>
    <message>
        <source>Half the axle: each wheel is a from the axle&apos;s centre, where the centre of mass is</source>
        <translation>Metade do eixo: cada roda fica a a do centro do eixo, onde está o centro de massa</translation>
    </message>
    <message>
        <source>wheel mass m</source>
        <translation>massa da roda m</translation>
    </message>
    <message>
        <source>The mass of each wheel</source>
        <translation>A massa de cada roda</translation>
    </message>
    <message>
        <source>Each wheel&apos;s moment of inertia about the axle</source>
        <translation>O momento de inércia de cada roda em relação ao eixo</translation>
    </message>
    <message>
        <source>Each wheel&apos;s moment of inertia about a vertical diameter</source>
        <translation>O momento de inércia de cada roda em relação a um diâmetro vertical</translation>
    </message>
    <message>
        <source>carriage body mass M</source>
        <translation>massa do corpo do carrinho M</translation>
    </message>
    <message>
        <source>The mass of the body without its wheels</source>
        <translation>A massa do corpo sem as rodas</translation>
    </message>
    <message>
        <source>body&apos;s moment of inertia I about the axle&apos;s centre</source>
        <translation>momento de inércia I do corpo em relação ao centro do eixo</translation>
    </message>
    <message>
        <source>The body&apos;s moment of inertia about the vertical axis through the axle&apos;s centre</source>
        <translation>O momento de inércia do corpo em relação ao eixo vertical que passa pelo centro do eixo</translation>
    </message>
    <message>
        <source>speed</source>
        <translation>velocidade</translation>
    </message>
    <message>
        <source>v_T = √(2T/m_eff), the speed the kinetic energy is worth</source>
        <translation>v_T = √(2T/m_eff), a velocidade que corresponde à energia cinética</translation>
    </message>
    <message>
        <source>v_s, the constant speed of P along the path</source>
        <translation>v_s, a velocidade constante de P ao longo do caminho</translation>
    </message>
    <message>
        <source>half-axle a (wheels at ±a across the heading)</source>
        <translation>semieixo a (rodas em ±a, transversais à direção)</translation>
    </message>
</context>
<context>
    <name>VectorPainter</name>
    <message>
        <source>Knife point velocity v_P</source>
        <translation>Velocidade do ponto da lâmina v_P</translation>
    </message>
    <message>
        <source>Control force along the axis f_s</source>
        <translation>Força de controle ao longo do eixo f_s</translation>
    </message>
    <message>
        <source>Knife&apos;s lateral reaction N (at P)</source>
        <translation>Reação lateral da lâmina N (em P)</translation>
    </message>
    <message>
        <source>Control couple τ</source>
        <translation>Torque de controle τ</translation>
    </message>
    <message>
        <source>Centre of mass velocity v_C</source>
        <translation>Velocidade do centro de massa v_C</translation>
    </message>
    <message>
        <source>τ = 0 while turning in place</source>
        <translation>τ = 0 durante o giro no lugar</translation>
    </message>
</context>
<context>
    <name>WheelInset</name>
    <message>
        <source>Side view, ahead →</source>
        <translation>Vista lateral, à frente →</translation>
    </message>
    <message>
        <source>θ = %1 rad</source>
        <translation>θ = %1 rad</translation>
    </message>
    <message>
        <source>1 right: θ₁ = %1 rad</source>
        <translation>1 direita: θ₁ = %1 rad</translation>
    </message>
    <message>
        <source>2 left: θ₂ = %1 rad</source>
        <translation>2 esquerda: θ₂ = %1 rad</translation>
    </message>
</context>
<context>
    <name>WorkPrecisionPlot</name>
    <message>
        <source>seconds per solve</source>
        <translation>segundos por solução</translation>
    </message>
    <message>
        <source>max position error [m]</source>
        <translation>erro máximo de posição [m]</translation>
    </message>
    <message>
        <source>controlled, t ≤ %1 s</source>
        <translation>controlado, t ≤ %1 s</translation>
    </message>
    <message>
        <source>free, t ≤ %1 s</source>
        <translation>livre, t ≤ %1 s</translation>
    </message>
    <message>
        <source>Work-precision: error against cost per solve</source>
        <translation>Trabalho-precisão: erro em função do custo por solução</translation>
    </message>
    <message>
        <source>chosen: see the table</source>
        <translation>escolhido: veja a tabela</translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::AccuracyReadout</name>
    <message>
        <source>Distance of the controlled knife point P from the prescribed path&apos;s own point at the same arc length: the tracking constraint residual</source>
        <translation>Distância do ponto da lâmina P controlado ao ponto do caminho prescrito com o mesmo comprimento de arco: o resíduo do vínculo de rastreamento</translation>
    </message>
    <message>
        <source>Distance from the paper&apos;s closed form (line and circle presets, constant energy)</source>
        <translation>Distância da forma fechada do artigo (predefinições reta e círculo, energia constante)</translation>
    </message>
    <message>
        <source>t</source>
        <translation>t</translation>
    </message>
    <message>
        <source>off the path</source>
        <translation>fora do caminho</translation>
    </message>
    <message>
        <source>vs closed form</source>
        <translation>fora da forma fechada</translation>
    </message>
    <message>
        <source>energy drift</source>
        <translation>deriva da energia</translation>
    </message>
    <message>
        <source>free energy drift</source>
        <translation>deriva da energia livre</translation>
    </message>
    <message>
        <source>&lt;b&gt;Models and methods&lt;/b&gt;</source>
        <translation>&lt;b&gt;Modelos e métodos&lt;/b&gt;</translation>
    </message>
    <message>
        <source>%1 (paper %2)</source>
        <translation>%1 (artigo %2)</translation>
    </message>
    <message>
        <source>no closed form for this scene</source>
        <translation>sem forma fechada para esta cena</translation>
    </message>
    <message>
        <source>T varies by design in constant-speed mode</source>
        <translation>T varia por construção no modo de velocidade constante</translation>
    </message>
    <message>
        <source>Details</source>
        <translation>Detalhes</translation>
    </message>
    <message>
        <source>The models and numerical methods in technical terms</source>
        <translation>Os modelos e os métodos numéricos em termos técnicos</translation>
    </message>
    <message>
        <source>How far the planned motion&apos;s end is from the target pose: |Δx|/b + |Δy|/b + |Δφ mod 2π|, from its closed form</source>
        <translation>A distância do fim do movimento planejado à pose alvo: |Δx|/b + |Δy|/b + |Δφ mod 2π|, da sua forma fechada</translation>
    </message>
    <message>
        <source>A motion is the fastest to the target up to its cut time, the first time another motion of the same length meets it</source>
        <translation>Um movimento é o mais rápido até o alvo até o seu tempo de corte, o primeiro instante em que outro movimento do mesmo comprimento o encontra</translation>
    </message>
    <message>
        <source>end error</source>
        <translation>erro no fim</translation>
    </message>
    <message>
        <source>optimal</source>
        <translation>ótimo</translation>
    </message>
    <message>
        <source>&lt;b&gt;Plan: motion %1 of %2&lt;/b&gt; (t = %3 s)</source>
        <translation>&lt;b&gt;Plano: movimento %1 de %2&lt;/b&gt; (t = %3 s)</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>certified: t ≤ cut time %1</source>
        <translation>certificado: t ≤ tempo de corte %1</translation>
    </message>
    <message>
        <source>no: t &gt; cut time %1, a faster motion exists</source>
        <translation>não: t &gt; tempo de corte %1, existe um movimento mais rápido</translation>
    </message>
    <message>
        <source>not certified (cut time %1)</source>
        <translation>não certificado (tempo de corte %1)</translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::AnimationDialog</name>
    <message>
        <source>Export animation</source>
        <translation>Exportar animação</translation>
    </message>
    <message>
        <source>clip.gif, clip.mp4, or frames/ for PNG frames</source>
        <translation>clipe.gif, clipe.mp4 ou quadros/ para quadros PNG</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>Procurar…</translation>
    </message>
    <message>
        <source>px</source>
        <translation>px</translation>
    </message>
    <message>
        <source>Plots beside the canvas</source>
        <translation>Gráficos ao lado da tela de desenho</translation>
    </message>
    <message>
        <source>GIF and MP4 need the ffmpeg program; a folder gets PNG frames.</source>
        <translation>GIF e MP4 precisam do programa ffmpeg; uma pasta recebe quadros PNG.</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Exportar</translation>
    </message>
    <message>
        <source>File</source>
        <translation>Arquivo</translation>
    </message>
    <message>
        <source>Frame rate</source>
        <translation>Taxa de quadros</translation>
    </message>
    <message>
        <source>Size</source>
        <translation>Tamanho</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Velocidade</translation>
    </message>
    <message>
        <source>MP4 video (*.mp4);;GIF (*.gif);;PNG frames into a folder (*)</source>
        <translation>Vídeo MP4 (*.mp4);;GIF (*.gif);;Quadros PNG numa pasta (*)</translation>
    </message>
    <message>
        <source>fps</source>
        <translation>qps</translation>
    </message>
    <message>
        <source>width</source>
        <translation>largura</translation>
    </message>
    <message>
        <source>height</source>
        <translation>altura</translation>
    </message>
    <message>
        <source>× real time</source>
        <translation>× tempo real</translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::Autosave</name>
    <message>
        <source>cannot open &apos;%1&apos;</source>
        <translation>não é possível abrir &apos;%1&apos;</translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::BodyDiagram</name>
    <message>
        <source>Drawing of the body on its path with the angles Ψ, φ and χ</source>
        <translation>Desenho do corpo no seu caminho com os ângulos Ψ, φ e χ</translation>
    </message>
    <message>
        <source>path</source>
        <translation>caminho</translation>
    </message>
    <message>
        <source>ghost: no control</source>
        <translation>fantasma: sem controle</translation>
    </message>
    <message>
        <source>vakonomic body</source>
        <translation>corpo vakonômico</translation>
    </message>
    <message>
        <source>control: χ = Ψ − (a/b)φ,</source>
        <translation>controle: χ = Ψ − (a/b)φ,</translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::BodyDisplayMenu</name>
    <message>
        <source>&amp;Bodies</source>
        <translation>&amp;Corpos</translation>
    </message>
    <message>
        <source>To &amp;scale</source>
        <translation>Em &amp;escala</translation>
    </message>
    <message>
        <source>&amp;Outline only</source>
        <translation>Só o &amp;contorno</translation>
    </message>
    <message>
        <source>Small &amp;marker (knife and centre of mass)</source>
        <translation>&amp;Marcador pequeno (lâmina e centro de massa)</translation>
    </message>
    <message>
        <source>Ctrl+Shift+1</source>
        <translation>Ctrl+Shift+1</translation>
    </message>
    <message>
        <source>Ctrl+Shift+2</source>
        <translation>Ctrl+Shift+2</translation>
    </message>
    <message>
        <source>Ctrl+Shift+3</source>
        <translation>Ctrl+Shift+3</translation>
    </message>
    <message>
        <source>&amp;Trail width</source>
        <translation>Largura do &amp;rastro</translation>
    </message>
    <message>
        <source>%1 px</source>
        <translation>%1 px</translation>
    </message>
    <message>
        <source>Body &amp;opacity</source>
        <translation>&amp;Opacidade do corpo</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>&amp;Automatic: to scale unless the body hides the path</source>
        <translation>&amp;Automático: em escala, a menos que o corpo esconda o caminho</translation>
    </message>
    <message>
        <source>Ctrl+Shift+0</source>
        <translation>Ctrl+Shift+0</translation>
    </message>
    <message>
        <source>Side view of the &amp;wheels</source>
        <translation>&amp;Vista lateral das rodas</translation>
    </message>
    <message>
        <source>Ctrl+Shift+4</source>
        <translation>Ctrl+Shift+4</translation>
    </message>
    <message>
        <source>A side view of the disk&apos;s or the carriage&apos;s wheels in a corner of the canvas, their spokes turning by the rolling angle</source>
        <translation>Uma vista lateral das rodas do disco ou do carrinho num canto da tela, com os raios girando pelo ângulo de rolamento</translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::CompareMenu</name>
    <message>
        <source>&amp;Compare</source>
        <translation>&amp;Comparar</translation>
    </message>
    <message>
        <source>&amp;Pin this run</source>
        <translation>&amp;Fixar esta execução</translation>
    </message>
    <message>
        <source>Ctrl+Shift+P</source>
        <translation>Ctrl+Shift+P</translation>
    </message>
    <message>
        <source>At most %1 pinned runs: clear them first</source>
        <translation>No máximo %1 execuções fixadas: limpe-as primeiro</translation>
    </message>
    <message>
        <source>Pin this run</source>
        <translation>Fixar esta execução</translation>
    </message>
    <message>
        <source>Keep this motion as a faint overlay on the canvas and the plots</source>
        <translation>Manter este movimento como uma sobreposição esmaecida na tela de desenho e nos gráficos</translation>
    </message>
    <message>
        <source>&amp;Clear pins</source>
        <translation>&amp;Limpar execuções fixadas</translation>
    </message>
    <message>
        <source>Clear pins</source>
        <translation>Limpar execuções fixadas</translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::DockLayout</name>
    <message>
        <source>Path</source>
        <translation>Caminho</translation>
    </message>
    <message>
        <source>System and parameters</source>
        <translation>Sistema e parâmetros</translation>
    </message>
    <message>
        <source>Plots</source>
        <translation>Gráficos</translation>
    </message>
    <message>
        <source>Methods</source>
        <translation>Métodos</translation>
    </message>
    <message>
        <source>Sweep</source>
        <translation>Varredura</translation>
    </message>
    <message>
        <source>Accuracy</source>
        <translation>Precisão</translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::ExportReport</name>
    <message>
        <source>Open folder</source>
        <translation>Abrir pasta</translation>
    </message>
    <message>
        <source>Show the written files in the file manager</source>
        <translation>Mostrar os arquivos gravados no gerenciador de arquivos</translation>
    </message>
    <message>
        <source>Dismiss</source>
        <translation>Dispensar</translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::GalleryMenu</name>
    <message>
        <source>&amp;Gallery</source>
        <translation>&amp;Galeria</translation>
    </message>
    <message>
        <source> (refused)</source>
        <translation> (recusado)</translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::HelpWindow</name>
    <message>
        <source>User guide</source>
        <translation>Guia do usuário</translation>
    </message>
    <message>
        <source>Physics notes</source>
        <translation>Notas de física</translation>
    </message>
    <message>
        <source>Numerical methods</source>
        <translation>Métodos numéricos</translation>
    </message>
    <message>
        <source>Robustness</source>
        <translation>Robustez</translation>
    </message>
    <message>
        <source>Architecture</source>
        <translation>Arquitetura</translation>
    </message>
    <message>
        <source>Chaplygin Lab help</source>
        <translation>Ajuda do Chaplygin Lab</translation>
    </message>
    <message>
        <source>Help documents</source>
        <translation>Documentos de ajuda</translation>
    </message>
    <message>
        <source>Help text</source>
        <translation>Texto de ajuda</translation>
    </message>
    <message>
        <source>en</source>
        <comment>the language code of this catalogue, as in docs/user-guide.CODE.md</comment>
        <translation>pt_BR</translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::IntroductionWindow</name>
    <message>
        <source>What am I looking at?</source>
        <translation>O que estou vendo?</translation>
    </message>
    <message>
        <source>Don&apos;t show this at start</source>
        <translation>Não mostrar ao iniciar</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;Plan&lt;/b&gt; (Edit menu) turns this round: drag a target pose and the program finds every vakonomic motion from the start that reaches it, choosing only λ(0). The fastest is drawn in full and certified; the fainter ones arrive later, each labelled with its time. Where two are equally fast, both are drawn in full.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;Planejar&lt;/b&gt; (menu Editar) inverte a pergunta: arraste uma pose alvo e o programa encontra todo movimento vakonômico que a alcança a partir do início, escolhendo apenas λ(0). O mais rápido é desenhado em traço cheio e certificado; os mais tênues chegam depois, cada um com seu tempo. Onde dois são igualmente rápidos, ambos são desenhados em traço cheio.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;On the screen.&lt;/b&gt; The big picture in the middle is the &lt;b&gt;canvas&lt;/b&gt;: the &lt;b&gt;path&lt;/b&gt; is the broad band, red where it turns right, grey where it runs straight and blue where it turns left, from its dot (the start) to its square (the end). The solid dark blue body follows it and leaves a trail; the dashed red ghost and the dash-dotted purple body start with it and go their own ways. The legend under the canvas names each line.&lt;/p&gt;&lt;p&gt;The &lt;b&gt;four plots&lt;/b&gt; below show, against time, the control angle Ψ, the angle χ the control turns, how hard it turns it (λ) and the kinetic energy T. The &lt;b&gt;green line&lt;/b&gt; in each plot is the moment the canvas shows; click a plot to go to that moment.&lt;/p&gt;&lt;p&gt;&lt;b&gt;To play&lt;/b&gt;, press &lt;b&gt;Space&lt;/b&gt; or the play button at the bottom; drag the slider beside it to move through time, &lt;b&gt;Home&lt;/b&gt; goes back to the start. The keys &lt;b&gt;1&lt;/b&gt; to &lt;b&gt;4&lt;/b&gt; load the paper&apos;s four examples, &lt;b&gt;Page Down&lt;/b&gt; the gallery&apos;s next scene; &lt;b&gt;Ctrl+Z&lt;/b&gt; takes any of them back.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;Na tela.&lt;/b&gt; A figura grande no meio é a &lt;b&gt;tela de desenho&lt;/b&gt;: o &lt;b&gt;caminho&lt;/b&gt; é a faixa larga, vermelha onde vira à direita, cinza onde segue reto e azul onde vira à esquerda, do seu ponto (o início) ao seu quadrado (o fim). O corpo azul-escuro de traço cheio o segue e deixa um rastro; o fantasma vermelho tracejado e o corpo roxo de traço e ponto partem com ele e seguem seus próprios caminhos. A legenda sob a tela de desenho dá o nome de cada linha.&lt;/p&gt;&lt;p&gt;Os &lt;b&gt;quatro gráficos&lt;/b&gt; abaixo mostram, ao longo do tempo, o ângulo de controle Ψ, o ângulo χ que o controle gira, a força com que o gira (λ) e a energia cinética T. A &lt;b&gt;linha verde&lt;/b&gt; em cada gráfico é o instante que a tela de desenho mostra; clique num gráfico para ir a esse instante.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Para reproduzir&lt;/b&gt;, aperte &lt;b&gt;Espaço&lt;/b&gt; ou o botão de reproduzir embaixo; arraste o controle deslizante ao lado para percorrer o tempo, &lt;b&gt;Home&lt;/b&gt; volta ao início. As teclas &lt;b&gt;1&lt;/b&gt; a &lt;b&gt;4&lt;/b&gt; carregam os quatro exemplos do artigo, &lt;b&gt;Page Down&lt;/b&gt; a próxima cena da galeria; &lt;b&gt;Ctrl+Z&lt;/b&gt; desfaz qualquer um deles.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;The physics.&lt;/b&gt; A &lt;b&gt;body&lt;/b&gt; (a sleigh, a rolling disk or a two-wheeled carriage) rests on a knife edge at &lt;b&gt;P&lt;/b&gt;: P moves only along the body&apos;s heading φ, never sideways. A control inside the body steers it so that P follows the &lt;b&gt;path&lt;/b&gt;.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Ψ&lt;/b&gt;, the control angle, splits the body&apos;s energy between driving and turning: ṡ = v&lt;sub&gt;T&lt;/sub&gt; sin Ψ and bφ̇ = v&lt;sub&gt;T&lt;/sub&gt; cos Ψ (the triangle). On a straight path Ψ = π/2; the path&apos;s curvature κ fixes it, tan Ψ = 1/(bκ).&lt;/p&gt;&lt;p&gt;&lt;b&gt;χ&lt;/b&gt; = Ψ − (a/b)φ is the angle the control turns, and &lt;b&gt;λ&lt;/b&gt; = m b χ̇ is how hard it turns it: a push λφ̇ along the heading and a couple −λṡ, which at constant energy do no work.&lt;/p&gt;&lt;p&gt;The &lt;b&gt;ghost&lt;/b&gt; is the same body from the same start with no control (λ = 0): its turning dies away, the knife lets it go only straight on, and it leaves the path. The &lt;b&gt;vakonomic body&lt;/b&gt; obeys the other mechanics the paper discusses: its λ follows an equation of its own, only its start can be chosen, and it cannot keep to the path either.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;A física.&lt;/b&gt; Um &lt;b&gt;corpo&lt;/b&gt; (um trenó, um disco que rola ou um carrinho de duas rodas) apoia-se numa lâmina em &lt;b&gt;P&lt;/b&gt;: P só se move na direção do corpo φ, nunca de lado. Um controle dentro do corpo o dirige de modo que P siga o &lt;b&gt;caminho&lt;/b&gt;.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Ψ&lt;/b&gt;, o ângulo de controle, reparte a energia do corpo entre avançar e girar: ṡ = v&lt;sub&gt;T&lt;/sub&gt; sen Ψ e bφ̇ = v&lt;sub&gt;T&lt;/sub&gt; cos Ψ (o triângulo). Num caminho reto Ψ = π/2; a curvatura κ do caminho o fixa, tan Ψ = 1/(bκ).&lt;/p&gt;&lt;p&gt;&lt;b&gt;χ&lt;/b&gt; = Ψ − (a/b)φ é o ângulo que o controle gira, e &lt;b&gt;λ&lt;/b&gt; = m b χ̇ é a força com que o gira: um empurrão λφ̇ na direção do corpo e um torque −λṡ, que, com energia constante, não realizam trabalho.&lt;/p&gt;&lt;p&gt;O &lt;b&gt;fantasma&lt;/b&gt; é o mesmo corpo, do mesmo início, sem controle (λ = 0): seu giro se extingue, a lâmina só o deixa seguir em frente, e ele sai do caminho. O &lt;b&gt;corpo vakonômico&lt;/b&gt; obedece à outra mecânica que o artigo discute: seu λ segue uma equação própria, só o seu início pode ser escolhido, e ele também não consegue se manter no caminho.&lt;/p&gt;</translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::LanguageMenu</name>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Idioma</translation>
    </message>
    <message>
        <source>System</source>
        <translation>Sistema</translation>
    </message>
    <message>
        <source>Takes effect at the next start of Chaplygin Lab</source>
        <translation>Vale a partir da próxima vez que o Chaplygin Lab for iniciado</translation>
    </message>
    <message>
        <source>Takes effect at the next start</source>
        <translation>Vale a partir do próximo início</translation>
    </message>
    <message>
        <source>%1 (not installed)</source>
        <translation>%1 (não instalado)</translation>
    </message>
    <message>
        <source>The catalogue of this language is not installed</source>
        <translation>O catálogo deste idioma não está instalado</translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::LecturePanel</name>
    <message>
        <source>Title of the lecture</source>
        <translation>Título da aula</translation>
    </message>
    <message>
        <source>The lecture&apos;s scenes in order: Page Down and Page Up step through them; double click shows one, F2 renames it</source>
        <translation>As cenas da aula em ordem: Page Down e Page Up passam por elas; um duplo clique mostra uma, F2 a renomeia</translation>
    </message>
    <message>
        <source>Scene %1</source>
        <translation>Cena %1</translation>
    </message>
    <message>
        <source>Scene %1 of %2</source>
        <translation>Cena %1 de %2</translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::MainWindow</name>
    <message>
        <source>Type a path</source>
        <translation>Digitar um caminho</translation>
    </message>
    <message>
        <source>Change the corners</source>
        <translation>Alterar os cantos</translation>
    </message>
    <message>
        <source>Draw a path</source>
        <translation>Desenhar um caminho</translation>
    </message>
    <message>
        <source>Edit the drawn path</source>
        <translation>Editar o caminho desenhado</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Arquivo</translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation>&amp;Novo</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>&amp;Abrir…</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>Abrir &amp;recente</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Salvar</translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation>Salvar c&amp;omo…</translation>
    </message>
    <message>
        <source>Export &amp;plots…</source>
        <translation>Exportar &amp;gráficos…</translation>
    </message>
    <message>
        <source>Ctrl+E</source>
        <translation>Ctrl+E</translation>
    </message>
    <message>
        <source>Export &amp;CSV…</source>
        <translation>Exportar &amp;CSV…</translation>
    </message>
    <message>
        <source>Ctrl+Shift+E</source>
        <translation>Ctrl+Shift+E</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>Sa&amp;ir</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Editar</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Desfazer</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Refazer</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>E&amp;xibir</translation>
    </message>
    <message>
        <source>Ctrl+0</source>
        <translation>Ctrl+0</translation>
    </message>
    <message>
        <source>F&amp;ollow body</source>
        <translation>&amp;Seguir o corpo</translation>
    </message>
    <message>
        <source>Ctrl+B</source>
        <translation>Ctrl+B</translation>
    </message>
    <message>
        <source>Zoom &amp;in</source>
        <translation>Am&amp;pliar</translation>
    </message>
    <message>
        <source>Zoom &amp;out</source>
        <translation>&amp;Reduzir</translation>
    </message>
    <message>
        <source>&amp;Animation</source>
        <translation>A&amp;nimação</translation>
    </message>
    <message>
        <source>&amp;Methods</source>
        <translation>&amp;Métodos</translation>
    </message>
    <message>
        <source>Compute &amp;work-precision</source>
        <translation>Calcular &amp;trabalho-precisão</translation>
    </message>
    <message>
        <source>Ctrl+Shift+W</source>
        <translation>Ctrl+Shift+W</translation>
    </message>
    <message>
        <source>&amp;Cancel work-precision</source>
        <translation>&amp;Cancelar trabalho-precisão</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>A&amp;juda</translation>
    </message>
    <message>
        <source>&amp;Physics notes</source>
        <translation>Notas de &amp;física</translation>
    </message>
    <message>
        <source>&amp;About Chaplygin Lab</source>
        <translation>&amp;Sobre o Chaplygin Lab</translation>
    </message>
    <message>
        <source>About Chaplygin Lab</source>
        <translation>Sobre o Chaplygin Lab</translation>
    </message>
    <message>
        <source>Preset %1</source>
        <translation>Predefinição %1</translation>
    </message>
    <message>
        <source>Tabulating the path…</source>
        <translation>Tabulando o caminho…</translation>
    </message>
    <message>
        <source>Refused: %1</source>
        <translation>Recusado: %1</translation>
    </message>
    <message>
        <source>Gallery: %1</source>
        <translation>Galeria: %1</translation>
    </message>
    <message>
        <source>Chaplygin Lab</source>
        <translation>Chaplygin Lab</translation>
    </message>
    <message>
        <source>The scene has unsaved changes. Save them?</source>
        <translation>A cena tem alterações não salvas. Salvá-las?</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 salvo</translation>
    </message>
    <message>
        <source>Plots written to %1</source>
        <translation>Gráficos gravados em %1</translation>
    </message>
    <message>
        <source>Open scene</source>
        <translation>Abrir cena</translation>
    </message>
    <message>
        <source>Save scene</source>
        <translation>Salvar cena</translation>
    </message>
    <message>
        <source>Scenes (*.json)</source>
        <translation>Cenas (*.json)</translation>
    </message>
    <message>
        <source>Export plots (PNG, PDF and SVG) into</source>
        <translation>Exportar gráficos (PNG, PDF e SVG) para</translation>
    </message>
    <message>
        <source>Export CSV</source>
        <translation>Exportar CSV</translation>
    </message>
    <message>
        <source>CSV (*.csv)</source>
        <translation>CSV (*.csv)</translation>
    </message>
    <message>
        <source>untitled</source>
        <translation>sem título</translation>
    </message>
    <message>
        <source>%1%2 — Chaplygin Lab</source>
        <translation>%1%2 — Chaplygin Lab</translation>
    </message>
    <message>
        <source>Notes</source>
        <translation>Notas</translation>
    </message>
    <message>
        <source>Equations</source>
        <translation>Equações</translation>
    </message>
    <message>
        <source>Edit the note</source>
        <translation>Editar a nota</translation>
    </message>
    <message>
        <source>Export &amp;animation…</source>
        <translation>Exportar ani&amp;mação…</translation>
    </message>
    <message>
        <source>Animation export cancelled</source>
        <translation>Exportação da animação cancelada</translation>
    </message>
    <message>
        <source>The note is %1 bytes; a note is at most %2 bytes (not kept)</source>
        <translation>A nota tem %1 bytes; uma nota tem no máximo %2 bytes (não mantida)</translation>
    </message>
    <message>
        <source>Ctrl+Y</source>
        <translation>Ctrl+Y</translation>
    </message>
    <message>
        <source>Ctrl+Shift+Z</source>
        <translation>Ctrl+Shift+Z</translation>
    </message>
    <message>
        <source>Genuine &amp;vakonomic body</source>
        <translation>Corpo vak&amp;onômico genuíno</translation>
    </message>
    <message>
        <source>Draw a third body whose multiplier obeys its own equation (21): it cannot follow the path</source>
        <translation>Desenhar um terceiro corpo cujo multiplicador obedece à sua própria equação (21): ele não consegue seguir o caminho</translation>
    </message>
    <message>
        <source>Play &amp;new scenes at once</source>
        <translation>Reproduzir &amp;novas cenas imediatamente</translation>
    </message>
    <message>
        <source>Preset %1: %2</source>
        <translation>Predefinição %1: %2</translation>
    </message>
    <message>
        <source>&amp;Help for this part of the window</source>
        <translation>&amp;Ajuda para esta parte da janela</translation>
    </message>
    <message>
        <source>&amp;User guide</source>
        <translation>&amp;Guia do usuário</translation>
    </message>
    <message>
        <source>&amp;Numerical methods</source>
        <translation>Métodos &amp;numéricos</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Chaplygin Lab %1&lt;/h3&gt;&lt;p&gt;Control of nonholonomic Chaplygin systems for teaching: the sleigh, the rolling disk and the two-wheeled carriage follow a prescribed path, beside the free motion from the same start.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Paper:&lt;/b&gt; Antunes, Sigaud, de Moraes, &lt;i&gt;Controlling nonholonomic Chaplygin systems&lt;/i&gt;, Brazilian Journal of Physics (2009).&lt;/p&gt;&lt;p&gt;&lt;b&gt;Licence:&lt;/b&gt; GNU General Public License, version 3 or later (the file COPYING). Components keep their own licences: Qt %2 (LGPL v3), QCustomPlot (GPL v3), GiNaC (GPL v2 or later), GSL (GPL v3), muparser (BSD).&lt;/p&gt;&lt;p&gt;&lt;b&gt;Credits:&lt;/b&gt; the Chaplygin Lab contributors; the equations of motion after the paper above, re-derived in the physics notes (Help).&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Chaplygin Lab %1&lt;/h3&gt;&lt;p&gt;Controle de sistemas de Chaplygin não holonômicos para o ensino: o trenó, o disco rolante e o carrinho de duas rodas seguem um caminho prescrito, ao lado do movimento livre a partir do mesmo início.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Artigo:&lt;/b&gt; Antunes, Sigaud, de Moraes, &lt;i&gt;Controlling nonholonomic Chaplygin systems&lt;/i&gt;, Brazilian Journal of Physics (2009).&lt;/p&gt;&lt;p&gt;&lt;b&gt;Licença:&lt;/b&gt; GNU General Public License, versão 3 ou posterior (o arquivo COPYING). Os componentes mantêm as suas próprias licenças: Qt %2 (LGPL v3), QCustomPlot (GPL v3), GiNaC (GPL v2 ou posterior), GSL (GPL v3), muparser (BSD).&lt;/p&gt;&lt;p&gt;&lt;b&gt;Créditos:&lt;/b&gt; os colaboradores do Chaplygin Lab; as equações de movimento seguem o artigo acima e são deduzidas novamente nas notas de física (Ajuda).&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Restore the unsaved scene?</source>
        <translation>Restaurar a cena não salva?</translation>
    </message>
    <message>
        <source>Chaplygin Lab ended without saving the scene you were working on. A copy was kept at %1. Restore it?</source>
        <translation>O Chaplygin Lab terminou sem salvar a cena em que você trabalhava. Uma cópia foi guardada em %1. Restaurá-la?</translation>
    </message>
    <message>
        <source>Perturbation</source>
        <translation>Perturbação</translation>
    </message>
    <message>
        <source>Push the body</source>
        <translation>Empurrar o corpo</translation>
    </message>
    <message>
        <source>Pushed body, &amp;open loop</source>
        <translation>Corpo empurrado, malha &amp;aberta</translation>
    </message>
    <message>
        <source>With a perturbation: the body that keeps the nominal λ(t) after the push</source>
        <translation>Com perturbação: o corpo que mantém o λ(t) nominal após o empurrão</translation>
    </message>
    <message>
        <source>Pushed body, &amp;closed loop</source>
        <translation>Corpo empurrado, malha &amp;fechada</translation>
    </message>
    <message>
        <source>With a perturbation: the body the feedback steers back to the path</source>
        <translation>Com perturbação: o corpo que a realimentação traz de volta ao caminho</translation>
    </message>
    <message>
        <source>&amp;What am I looking at?</source>
        <translation>O &amp;que estou vendo?</translation>
    </message>
    <message>
        <source>Frames written to %1</source>
        <translation>Quadros gravados em %1</translation>
    </message>
    <message>
        <source>Animation written to %1</source>
        <translation>Animação gravada em %1</translation>
    </message>
    <message>
        <source>&amp;Reset layout</source>
        <translation>&amp;Restaurar a disposição</translation>
    </message>
    <message>
        <source>&amp;Fit the path</source>
        <translation>A&amp;justar ao caminho</translation>
    </message>
    <message>
        <source>Frame the path and the controlled body (F on the canvas)</source>
        <translation>Enquadrar o caminho e o corpo controlado (F na tela de desenho)</translation>
    </message>
    <message>
        <source>Fit &amp;everything that moves</source>
        <translation>Ajustar a &amp;tudo o que se move</translation>
    </message>
    <message>
        <source>Shift+F</source>
        <translation>Shift+F</translation>
    </message>
    <message>
        <source>P&amp;lan a motion (pose to pose)</source>
        <translation>P&amp;lanejar um movimento (de pose a pose)</translation>
    </message>
    <message>
        <source>Ctrl+Shift+T</source>
        <translation>Ctrl+Shift+T</translation>
    </message>
    <message>
        <source>Plan</source>
        <translation>Planejar</translation>
    </message>
    <message>
        <source>Plan: drag the target pose (its dot and its heading&apos;s handle; Shift snaps) and see every genuine vakonomic motion that reaches it, the fastest in full; click one to choose it</source>
        <translation>Planejar: arraste a pose alvo (seu ponto e a alça de sua direção; Shift ajusta à grade) e veja todo movimento vakonômico genuíno que a alcança, o mais rápido em traço cheio; clique num deles para escolhê-lo</translation>
    </message>
    <message>
        <source>Play the planned motion</source>
        <translation>Reproduzir o movimento planejado</translation>
    </message>
    <message>
        <source>Play plan</source>
        <translation>Tocar plano</translation>
    </message>
    <message>
        <source>Ctrl+Shift+Space</source>
        <translation>Ctrl+Shift+Space</translation>
    </message>
    <message>
        <source>The genuine vakonomic body along the chosen motion, with the free ghost from the same start</source>
        <translation>O corpo vakonômico genuíno ao longo do movimento escolhido, com o fantasma livre a partir do mesmo início</translation>
    </message>
    <message>
        <source>&amp;Track this plan</source>
        <translation>Segui&amp;r este plano</translation>
    </message>
    <message>
        <source>Track plan</source>
        <translation>Seguir plano</translation>
    </message>
    <message>
        <source>Make the chosen motion&apos;s knife track the path: the controlled body and the genuine vakonomic body then coincide</source>
        <translation>Tornar o rastro da lâmina do movimento escolhido o caminho: o corpo controlado e o corpo vakonômico genuíno então coincidem</translation>
    </message>
    <message>
        <source>Preset %1 loaded; Ctrl+Z goes back</source>
        <translation>Predefinição %1 carregada; Ctrl+Z desfaz</translation>
    </message>
    <message>
        <source>The system and its parameters</source>
        <translation>O sistema e seus parâmetros</translation>
    </message>
    <message>
        <source>Choosing a path</source>
        <translation>Escolhendo um caminho</translation>
    </message>
    <message>
        <source>Methods and accuracy</source>
        <translation>Métodos e precisão</translation>
    </message>
    <message>
        <source>Plots</source>
        <translation>Gráficos</translation>
    </message>
    <message>
        <source>Animation</source>
        <translation>Animação</translation>
    </message>
    <message>
        <source>Copy &amp;link</source>
        <translation>Copiar &amp;link</translation>
    </message>
    <message>
        <source>Ctrl+Shift+C</source>
        <translation>Ctrl+Shift+C</translation>
    </message>
    <message>
        <source>Put a chaplygin-lab: link that holds this scene on the clipboard, to paste into a chat, a course page or an e-mail</source>
        <translation>Coloca na área de transferência um link chaplygin-lab: que contém esta cena, para colar num chat, na página de um curso ou num e-mail</translation>
    </message>
    <message>
        <source>Open lin&amp;k…</source>
        <translation>Abrir lin&amp;k…</translation>
    </message>
    <message>
        <source>Cannot open the link: %1</source>
        <translation>Não foi possível abrir o link: %1</translation>
    </message>
    <message>
        <source>The scene does not solve (%1); fix it or undo before copying its link</source>
        <translation>A cena não tem solução (%1); corrija-a ou desfaça antes de copiar o link</translation>
    </message>
    <message numerus="yes">
        <source>Link copied: %n character(s)</source>
        <translation>
            <numerusform>Link copiado: %n caractere</numerusform>
            <numerusform>Link copiado: %n caracteres</numerusform>
        </translation>
    </message>
    <message>
        <source>Open link</source>
        <translation>Abrir link</translation>
    </message>
    <message>
        <source>A chaplygin-lab: link:</source>
        <translation>Um link chaplygin-lab:</translation>
    </message>
    <message>
        <source>CSV written to %1, its parameters to %2</source>
        <translation>CSV gravado em %1, seus parâmetros em %2</translation>
    </message>
    <message>
        <source>Plots&apos; &amp;time</source>
        <translation>&amp;Tempo dos gráficos</translation>
    </message>
    <message>
        <source>&amp;Measure (ruler, protractor, probe)</source>
        <translation>&amp;Medir (régua, transferidor, sonda)</translation>
    </message>
    <message>
        <source>Ctrl+Shift+M</source>
        <translation>Ctrl+Shift+M</translation>
    </message>
    <message>
        <source>Measure</source>
        <translation>Medir</translation>
    </message>
    <message>
        <source>Measure (M on the canvas): drag for a ruler, drag again from its end for an angle, start on a body to measure from its heading; hover the path or a trail for its values. Esc clears; the scene is not changed</source>
        <translation>Medir (M na tela de desenho): arraste para uma régua, arraste de novo a partir da ponta dela para um ângulo, comece num corpo para medir a partir do seu rumo; passe o mouse sobre o caminho ou um rastro para ver seus valores. Esc apaga; a cena não é alterada</translation>
    </message>
    <message>
        <source>Values</source>
        <translation>Valores</translation>
    </message>
    <message>
        <source>Ctrl+Shift+V</source>
        <translation>Ctrl+Shift+V</translation>
    </message>
    <message>
        <source>Scenes and lectures (*.json);;All files (*)</source>
        <translation>Cenas e aulas (*.json);;Todos os arquivos (*)</translation>
    </message>
    <message>
        <source>Lecture, %1 — %2</source>
        <translation>Aula, %1 — %2</translation>
    </message>
    <message>
        <source>Lecture</source>
        <translation>Aula</translation>
    </message>
    <message>
        <source>&amp;Lecture</source>
        <translation>Au&amp;la</translation>
    </message>
    <message>
        <source>&amp;New lecture</source>
        <translation>&amp;Nova aula</translation>
    </message>
    <message>
        <source>&amp;Open lecture…</source>
        <translation>&amp;Abrir aula…</translation>
    </message>
    <message>
        <source>Start from the &amp;gallery</source>
        <translation>Começar pela &amp;galeria</translation>
    </message>
    <message>
        <source>Gallery</source>
        <translation>Galeria</translation>
    </message>
    <message>
        <source>A new lecture with the gallery&apos;s scenes, to reorder and add to</source>
        <translation>Uma nova aula com as cenas da galeria, para reordenar e completar</translation>
    </message>
    <message>
        <source>&amp;Save lecture</source>
        <translation>&amp;Salvar aula</translation>
    </message>
    <message>
        <source>Save lecture &amp;as…</source>
        <translation>Salvar aula c&amp;omo…</translation>
    </message>
    <message>
        <source>&amp;Close lecture</source>
        <translation>&amp;Fechar aula</translation>
    </message>
    <message>
        <source>Page Down then steps through the gallery again</source>
        <translation>Page Down volta então a passar pela galeria</translation>
    </message>
    <message>
        <source>A&amp;dd the current scene</source>
        <translation>A&amp;dicionar a cena atual</translation>
    </message>
    <message>
        <source>Ctrl+L</source>
        <translation>Ctrl+L</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Adicionar</translation>
    </message>
    <message>
        <source>Add the current scene after the highlighted one (Ctrl+L)</source>
        <translation>Adicionar a cena atual depois da destacada (Ctrl+L)</translation>
    </message>
    <message>
        <source>&amp;Replace with the current scene</source>
        <translation>Substitui&amp;r pela cena atual</translation>
    </message>
    <message>
        <source>The highlighted entry becomes the scene as it is now</source>
        <translation>A entrada destacada passa a ser a cena como está agora</translation>
    </message>
    <message>
        <source>Re&amp;move from the lecture</source>
        <translation>Re&amp;mover da aula</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Remover</translation>
    </message>
    <message>
        <source>Move &amp;up</source>
        <translation>Mover para &amp;cima</translation>
    </message>
    <message>
        <source>Up</source>
        <translation>Subir</translation>
    </message>
    <message>
        <source>Move do&amp;wn</source>
        <translation>Mover para &amp;baixo</translation>
    </message>
    <message>
        <source>Down</source>
        <translation>Descer</translation>
    </message>
    <message>
        <source>Ne&amp;xt scene</source>
        <translation>&amp;Próxima cena</translation>
    </message>
    <message>
        <source>The lecture&apos;s next scene, or the gallery&apos;s when no lecture is open</source>
        <translation>A próxima cena da aula, ou a da galeria quando nenhuma aula está aberta</translation>
    </message>
    <message>
        <source>Pre&amp;vious scene</source>
        <translation>Cena an&amp;terior</translation>
    </message>
    <message>
        <source>scene %1 of %2</source>
        <translation>cena %1 de %2</translation>
    </message>
    <message>
        <source>Lecture: %1</source>
        <translation>Aula: %1</translation>
    </message>
    <message>
        <source>Lecture: %1%2</source>
        <translation>Aula: %1%2</translation>
    </message>
    <message>
        <source>Notes (%1)</source>
        <translation>Notas (%1)</translation>
    </message>
    <message>
        <source>The lecture has no scenes yet: Lecture ▸ Add the current scene (Ctrl+L)</source>
        <translation>A aula ainda não tem cenas: Aula ▸ Adicionar a cena atual (Ctrl+L)</translation>
    </message>
    <message>
        <source>The lecture&apos;s scene %1 does not run: %2</source>
        <translation>A cena %1 da aula não roda: %2</translation>
    </message>
    <message>
        <source>A lecture has at most %1 scenes; this one is full</source>
        <translation>Uma aula tem no máximo %1 cenas; esta está cheia</translation>
    </message>
    <message>
        <source>Added to the lecture as scene %1 of %2</source>
        <translation>Adicionada à aula como cena %1 de %2</translation>
    </message>
    <message>
        <source>A new lecture: add scenes to it with Lecture ▸ Add the current scene (Ctrl+L)</source>
        <translation>Uma nova aula: adicione cenas a ela com Aula ▸ Adicionar a cena atual (Ctrl+L)</translation>
    </message>
    <message>
        <source>Saved the lecture in %1</source>
        <translation>Aula salva em %1</translation>
    </message>
    <message>
        <source>Open lecture</source>
        <translation>Abrir aula</translation>
    </message>
    <message>
        <source>Lectures (*.json);;All files (*)</source>
        <translation>Aulas (*.json);;Todos os arquivos (*)</translation>
    </message>
    <message>
        <source>No lecture is open: Lecture ▸ New lecture</source>
        <translation>Nenhuma aula está aberta: Aula ▸ Nova aula</translation>
    </message>
    <message>
        <source>lecture</source>
        <translation>aula</translation>
    </message>
    <message>
        <source>Save lecture</source>
        <translation>Salvar aula</translation>
    </message>
    <message>
        <source>Lectures (*.json)</source>
        <translation>Aulas (*.json)</translation>
    </message>
    <message>
        <source>The lecture has unsaved changes. Save them?</source>
        <translation>A aula tem alterações não salvas. Salvá-las?</translation>
    </message>
    <message>
        <source>Save anno&amp;tations with the scene</source>
        <translation>Salvar as ano&amp;tações com a cena</translation>
    </message>
    <message>
        <source>File &gt; Save also writes the pen&apos;s marks into the scene file; the scene&apos;s link and its computation are unchanged</source>
        <translation>Arquivo &gt; Salvar escreve também as marcas da caneta no arquivo da cena; o link da cena e o seu cálculo não mudam</translation>
    </message>
    <message>
        <source>P&amp;en (draw over the canvas)</source>
        <translation>Can&amp;eta (desenhar sobre a tela)</translation>
    </message>
    <message>
        <source>Ctrl+Shift+D</source>
        <translation>Ctrl+Shift+D</translation>
    </message>
    <message>
        <source>Pen</source>
        <translation>Caneta</translation>
    </message>
    <message>
        <source>Pen (P on the canvas): drag to draw over the canvas, Shift+drag for an arrow; C: next colour, A: arrows; Ctrl+Z undoes the last mark, E or Delete clears them all. The marks follow zoom and pan; the scene is not changed</source>
        <translation>Caneta (P na tela de desenho): arraste para desenhar sobre a tela, Shift+arrastar para uma seta; C: próxima cor, A: setas; Ctrl+Z desfaz a última marca, E ou Delete apaga todas. As marcas acompanham a ampliação e o deslocamento; a cena não muda</translation>
    </message>
    <message>
        <source>Pen mar&amp;ks</source>
        <translation>Marcas da ca&amp;neta</translation>
    </message>
    <message>
        <source>&amp;Arrows (A on the canvas)</source>
        <translation>&amp;Setas (A na tela de desenho)</translation>
    </message>
    <message>
        <source>&amp;Undo last mark</source>
        <translation>&amp;Desfazer a última marca</translation>
    </message>
    <message>
        <source>&amp;Clear marks</source>
        <translation>&amp;Apagar as marcas</translation>
    </message>
    <message>
        <source>The scene is restored without the pen&apos;s marks, which were damaged: %1</source>
        <translation>A cena foi restaurada sem as marcas da caneta, que estavam danificadas: %1</translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::MeasureTool</name>
    <message>
        <source>%1 m at %2°</source>
        <translation>%1 m a %2°</translation>
    </message>
    <message>
        <source>angle %1°</source>
        <translation>ângulo %1°</translation>
    </message>
    <message>
        <source>%1° from the heading</source>
        <translation>%1° a partir do rumo</translation>
    </message>
    <message>
        <source>Path (controlled body)</source>
        <translation>Caminho (corpo controlado)</translation>
    </message>
    <message>
        <source>Free body&apos;s trail</source>
        <translation>Rastro do corpo livre</translation>
    </message>
    <message>
        <source>Vakonomic body&apos;s trail</source>
        <translation>Rastro do corpo vakonômico</translation>
    </message>
    <message>
        <source>Open-loop body&apos;s trail</source>
        <translation>Rastro do corpo em malha aberta</translation>
    </message>
    <message>
        <source>Feedback body&apos;s trail</source>
        <translation>Rastro do corpo com realimentação</translation>
    </message>
    <message>
        <source>t = %1 s</source>
        <translation>t = %1 s</translation>
    </message>
    <message>
        <source>s = %1 m</source>
        <translation>s = %1 m</translation>
    </message>
    <message>
        <source>x = %1 m, y = %2 m</source>
        <translation>x = %1 m, y = %2 m</translation>
    </message>
    <message>
        <source>φ = %1 rad (%2°)</source>
        <translation>φ = %1 rad (%2°)</translation>
    </message>
    <message>
        <source>κ = %1 1/m, ρ = %2 m</source>
        <translation>κ = %1 1/m, ρ = %2 m</translation>
    </message>
    <message>
        <source>Ψ = %1 rad (%2°)</source>
        <translation>Ψ = %1 rad (%2°)</translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::MethodsPanel</name>
    <message>
        <source>Compute work-precision</source>
        <translation>Calcular trabalho-precisão</translation>
    </message>
    <message>
        <source>Sweep every method&apos;s tolerances and step sizes for the current scene (Ctrl+Shift+W)</source>
        <translation>Varrer as tolerâncias e os passos de cada método para a cena atual (Ctrl+Shift+W)</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
    <message>
        <source>Error against cost per solve for every method: press Compute.</source>
        <translation>Erro em função do custo por solução para cada método: clique em Calcular.</translation>
    </message>
    <message>
        <source>problem</source>
        <translation>problema</translation>
    </message>
    <message>
        <source>chosen method</source>
        <translation>método escolhido</translation>
    </message>
    <message>
        <source>error [m]</source>
        <translation>erro [m]</translation>
    </message>
    <message>
        <source>s/solve</source>
        <translation>s/solução</translation>
    </message>
    <message>
        <source>Pareto</source>
        <translation>Pareto</translation>
    </message>
    <message>
        <source>Sweeping the methods in a worker thread…</source>
        <translation>Varrendo os métodos em uma thread de trabalho…</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>cancelado</translation>
    </message>
    <message>
        <source>Cancelling after the configuration under way…</source>
        <translation>Cancelando após a configuração em andamento…</translation>
    </message>
    <message>
        <source>cancelled: the scene changed</source>
        <translation>cancelado: a cena mudou</translation>
    </message>
    <message>
        <source>The sweep failed: %1</source>
        <translation>A varredura falhou: %1</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>sim</translation>
    </message>
    <message>
        <source>no</source>
        <translation>não</translation>
    </message>
    <message>
        <source>&lt;b&gt;References&lt;/b&gt;&lt;br&gt;controlled: %1&lt;br&gt;free: %2</source>
        <translation>&lt;b&gt;Referências&lt;/b&gt;&lt;br&gt;controlado: %1&lt;br&gt;livre: %2</translation>
    </message>
    <message>
        <source>%1 configurations; horizons %2 s (controlled), %3 s (free).</source>
        <translation>%1 configurações; horizontes %2 s (controlado), %3 s (livre).</translation>
    </message>
    <message>
        <source>Stopped (%1) after %2</source>
        <translation>Interrompido (%1) após %2</translation>
    </message>
    <message>
        <source>internal error: %1</source>
        <translation>erro interno: %1</translation>
    </message>
    <message>
        <source>The scene changed: press Compute for this scene&apos;s diagram.</source>
        <translation>A cena mudou: clique em Calcular para obter o diagrama desta cena.</translation>
    </message>
    <message>
        <source>controlled</source>
        <translation>controlado</translation>
    </message>
    <message>
        <source>free</source>
        <translation>livre</translation>
    </message>
    <message>
        <source>%1, Gauss–Kronrod 61 at tolerance 1e-14 (the tightest method)</source>
        <translation>%1, Gauss–Kronrod 61 com tolerância 1e-14 (o método mais rigoroso)</translation>
    </message>
    <message>
        <source>%1 (no independent method for this path)</source>
        <translation>%1 (não há método independente para este caminho)</translation>
    </message>
    <message>
        <source>controlled: %1
free: %2</source>
        <translation>controlado: %1
livre: %2</translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::NotesPanel</name>
    <message>
        <source>What to say about this scene (Markdown, saved with it)</source>
        <translation>O que dizer sobre esta cena (Markdown, salvo com ela)</translation>
    </message>
    <message>
        <source>Edit</source>
        <translation>Editar</translation>
    </message>
    <message>
        <source># Title

What the students should notice…</source>
        <translation># Título

O que os estudantes devem observar…</translation>
    </message>
    <message>
        <source>&lt;p style=&apos;color:#777&apos;&gt;No note for this scene. Click &lt;b&gt;Edit&lt;/b&gt; to write one; it is saved with the scene.&lt;/p&gt;</source>
        <translation>&lt;p style=&apos;color:#777&apos;&gt;Nenhuma nota para esta cena. Clique em &lt;b&gt;Editar&lt;/b&gt; para escrever uma; ela é salva com a cena.&lt;/p&gt;</translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::NumberField</name>
    <message>
        <source>%1 must be greater than %2</source>
        <translation>%1 deve ser maior que %2</translation>
    </message>
    <message>
        <source>%1 must be at least %2</source>
        <translation>%1 deve ser no mínimo %2</translation>
    </message>
    <message>
        <source>%1 must be less than %2</source>
        <translation>%1 deve ser menor que %2</translation>
    </message>
    <message>
        <source>%1 must be at most %2</source>
        <translation>%1 deve ser no máximo %2</translation>
    </message>
    <message>
        <source>%1 must be a whole number</source>
        <translation>%1 deve ser um número inteiro</translation>
    </message>
    <message>
        <source>invalid: %1</source>
        <translation>inválido: %1</translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::ParametersPanel</name>
    <message>
        <source>Chaplygin sleigh</source>
        <translation>Trenó de Chaplygin</translation>
    </message>
    <message>
        <source>Rolling disk (App. A)</source>
        <translation>Disco rolante (Apêndice A)</translation>
    </message>
    <message>
        <source>Two-wheeled carriage (App. B)</source>
        <translation>Carrinho de duas rodas (Apêndice B)</translation>
    </message>
    <message>
        <source>The Chaplygin system; each reduces to a sleigh with m_eff, a and b</source>
        <translation>O sistema de Chaplygin; cada um se reduz a um trenó com m_eff, a e b</translation>
    </message>
    <message>
        <source>&amp;System</source>
        <translation>&amp;Sistema</translation>
    </message>
    <message>
        <source>enter b, derive I</source>
        <translation>informar b, deduzir I</translation>
    </message>
    <message>
        <source>enter I, derive b</source>
        <translation>informar I, deduzir b</translation>
    </message>
    <message>
        <source>b² = a² + I/m: give the radius of gyration b [m] or the inertia I [kg m²]</source>
        <translation>b² = a² + I/m: informe o raio de giração b [m] ou o momento de inércia I [kg m²]</translation>
    </message>
    <message>
        <source>&amp;Gyration</source>
        <translation>&amp;Giração</translation>
    </message>
    <message>
        <source>What the control law uses: effective mass [kg], CM offset a [m], radius of gyration b about P [m], inertia I about the CM [kg m²]</source>
        <translation>O que a lei de controle usa: massa efetiva [kg], deslocamento a do CM [m], raio de giração b em relação a P [m], momento de inércia I em relação ao CM [kg m²]</translation>
    </message>
    <message>
        <source>constant kinetic energy (v_T)</source>
        <translation>energia cinética constante (v_T)</translation>
    </message>
    <message>
        <source>constant speed along the path (v_s)</source>
        <translation>velocidade constante ao longo do caminho (v_s)</translation>
    </message>
    <message>
        <source>Energy: T = m v_T²/2 fixed (sec. 4); speed: ds/dt = v_s fixed (App. C)</source>
        <translation>Energia: T = m v_T²/2 fixa (seção 4); velocidade: ds/dt = v_s fixa (Apêndice C)</translation>
    </message>
    <message>
        <source>&amp;Mode</source>
        <translation>&amp;Modo</translation>
    </message>
    <message>
        <source>speed</source>
        <translation>velocidade</translation>
    </message>
    <message>
        <source>(no valid system)</source>
        <translation>(nenhum sistema válido)</translation>
    </message>
    <message>
        <source>Change %1 to %2</source>
        <translation>Alterar %1 para %2</translation>
    </message>
    <message>
        <source>Choose the %1</source>
        <translation>Escolher o %1</translation>
    </message>
    <message>
        <source>Enter I instead of b</source>
        <translation>Informar I em vez de b</translation>
    </message>
    <message>
        <source>Enter b instead of I</source>
        <translation>Informar b em vez de I</translation>
    </message>
    <message>
        <source>Constant energy</source>
        <translation>Energia constante</translation>
    </message>
    <message>
        <source>Constant speed</source>
        <translation>Velocidade constante</translation>
    </message>
    <message>
        <source>m_eff = %1 kg, CM offset = %2 m, b = %3 m, I about the CM = %4 kg m²</source>
        <translation>m_eff = %1 kg, deslocamento do CM = %2 m, b = %3 m, I em relação ao CM = %4 kg m²</translation>
    </message>
    <message>
        <source>invalid: %1</source>
        <translation>inválido: %1</translation>
    </message>
    <message>
        <source>%1 [%2]: %3; slider %4 … %5 %2; type any value or an expression such as 2*pi or 1e6</source>
        <translation>%1 [%2]: %3; controle deslizante %4 … %5 %2; digite qualquer valor ou uma expressão como 2*pi ou 1e6</translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::PathPanel</name>
    <message>
        <source>Preset (the paper&apos;s examples)</source>
        <translation>Predefinição (os exemplos do artigo)</translation>
    </message>
    <message>
        <source>(choose a preset)</source>
        <translation>(escolha uma predefinição)</translation>
    </message>
    <message>
        <source>Load one of the paper&apos;s four examples with the paper&apos;s parameters</source>
        <translation>Carregar um dos quatro exemplos do artigo com os parâmetros do artigo</translation>
    </message>
    <message>
        <source>Typed path</source>
        <translation>Caminho digitado</translation>
    </message>
    <message>
        <source>graph y(x)</source>
        <translation>gráfico y(x)</translation>
    </message>
    <message>
        <source>parametric x(u), y(u)</source>
        <translation>paramétrico x(u), y(u)</translation>
    </message>
    <message>
        <source>y as a function of x [m], e.g. -sin(x) or 0.5*x + 1; press Enter to apply</source>
        <translation>y como função de x [m], p. ex. -sin(x) ou 0.5*x + 1; pressione Enter para aplicar</translation>
    </message>
    <message>
        <source>y(x) =</source>
        <translation>y(x) =</translation>
    </message>
    <message>
        <source>x as a function of u [m], e.g. 2*cos(u)</source>
        <translation>x como função de u [m], p. ex. 2*cos(u)</translation>
    </message>
    <message>
        <source>x(u) =</source>
        <translation>x(u) =</translation>
    </message>
    <message>
        <source>y as a function of u [m], e.g. 2*sin(u)</source>
        <translation>y como função de u [m], p. ex. 2*sin(u)</translation>
    </message>
    <message>
        <source>y(u) =</source>
        <translation>y(u) =</translation>
    </message>
    <message>
        <source>x from, to</source>
        <translation>x de, até</translation>
    </message>
    <message>
        <source>&amp;Apply path</source>
        <translation>&amp;Aplicar caminho</translation>
    </message>
    <message>
        <source>Tabulate the typed path (Enter in a field does the same)</source>
        <translation>Tabular o caminho digitado (Enter em um campo faz o mesmo)</translation>
    </message>
    <message>
        <source>Drawn path</source>
        <translation>Caminho desenhado</translation>
    </message>
    <message>
        <source>&amp;Draw on the canvas</source>
        <translation>&amp;Desenhar na tela de desenho</translation>
    </message>
    <message>
        <source>Press and drag on the canvas to draw a new path; it is sampled and smoothed</source>
        <translation>Pressione e arraste na tela de desenho para desenhar um novo caminho; ele é amostrado e suavizado</translation>
    </message>
    <message>
        <source>smooth (spline through the points)</source>
        <translation>suave (spline pelos pontos)</translation>
    </message>
    <message>
        <source>How a drawn path&apos;s corners are followed</source>
        <translation>Como os cantos de um caminho desenhado são seguidos</translation>
    </message>
    <message>
        <source>Smooth corners: spline bandwidth in point spacings (0 passes through every point)</source>
        <translation>Cantos suaves: largura de banda do spline em espaçamentos de pontos (0 passa por todos os pontos)</translation>
    </message>
    <message>
        <source>Smoothing</source>
        <translation>Suavização</translation>
    </message>
    <message>
        <source>u from, to</source>
        <translation>u de, até</translation>
    </message>
    <message>
        <source>Current path: %1 drawn points, %2 corners</source>
        <translation>Caminho atual: %1 pontos desenhados, cantos %2</translation>
    </message>
    <message>
        <source>pivot</source>
        <translation>em pivô</translation>
    </message>
    <message>
        <source>smooth</source>
        <translation>suaves</translation>
    </message>
    <message>
        <source>smooth (spline)</source>
        <translation>suave (spline)</translation>
    </message>
    <message>
        <source>pivot (turn in place)</source>
        <translation>pivô (giro no lugar)</translation>
    </message>
    <message>
        <source>x from</source>
        <translation>x de</translation>
    </message>
    <message>
        <source>x to</source>
        <translation>x até</translation>
    </message>
    <message>
        <source>The range of x [m] (graph) or of u (parametric), traversed from the first to the second; a number or an expression such as 2*pi; Enter applies the path</source>
        <translation>O intervalo de x [m] (gráfico) ou de u (paramétrico), percorrido do primeiro ao segundo; um número ou uma expressão como 2*pi; Enter aplica o caminho</translation>
    </message>
    <message>
        <source>pivot (turn in place where the stroke turns by more than the corner angle, smooth between)</source>
        <translation>pivô (gira no lugar onde o traço vira mais que o ângulo de canto, suave entre os cantos)</translation>
    </message>
    <message>
        <source>Corner angle</source>
        <translation>Ângulo de canto</translation>
    </message>
    <message>
        <source>Pivot corners: the stroke pivots where it turns by more than this angle between its neighbouring points; smaller turns are smoothed (docs/user-guide.md, Drawing a path)</source>
        <translation>Cantos com pivô: o traço pivota onde vira mais que este ângulo entre seus pontos vizinhos; viradas menores são suavizadas (docs/user-guide.md, Drawing a path)</translation>
    </message>
    <message>
        <source>u from</source>
        <translation>u de</translation>
    </message>
    <message>
        <source>u to</source>
        <translation>u até</translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::PenTool</name>
    <message>
        <source>Blue</source>
        <translation>Azul</translation>
    </message>
    <message>
        <source>Green</source>
        <translation>Verde</translation>
    </message>
    <message>
        <source>Black</source>
        <translation>Preto</translation>
    </message>
    <message>
        <source>Red</source>
        <translation>Vermelho</translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::PerturbationPanel</name>
    <message>
        <source>Perturbed bodies (open loop and feedback)</source>
        <translation>Corpos perturbados (malha aberta e realimentação)</translation>
    </message>
    <message>
        <source>Two more bodies start from the controlled one moved by the offsets and get the push: one keeps the nominal λ(t), one is steered back by feedback (docs/physics.md §9)</source>
        <translation>Mais dois corpos partem do controlado deslocados pelos desvios e recebem o empurrão: um mantém o λ(t) nominal, o outro é trazido de volta por realimentação (docs/physics.md §9)</translation>
    </message>
    <message>
        <source>offset dy (left)</source>
        <translation>deslocamento dy (à esquerda)</translation>
    </message>
    <message>
        <source>heading offset dφ</source>
        <translation>desvio de rumo dφ</translation>
    </message>
    <message>
        <source>control angle offset dΨ</source>
        <translation>desvio do ângulo de controle dΨ</translation>
    </message>
    <message>
        <source>push at t</source>
        <translation>empurrão em t</translation>
    </message>
    <message>
        <source>push: Ψ jumps by</source>
        <translation>empurrão: Ψ salta</translation>
    </message>
    <message>
        <source>push: P moves left by</source>
        <translation>empurrão: P vai à esquerda</translation>
    </message>
    <message>
        <source>feedback rate P</source>
        <translation>taxa de realimentação P</translation>
    </message>
    <message>
        <source>limit |Ψ̇| to</source>
        <translation>limitar |Ψ̇| a</translation>
    </message>
    <message>
        <source>rad/s</source>
        <translation>rad/s</translation>
    </message>
    <message>
        <source>controller&apos;s b</source>
        <translation>b do controlador</translation>
    </message>
    <message>
        <source>The b the feedback assumes; unchecked, the plant&apos;s own</source>
        <translation>O b que a realimentação supõe; desmarcado, o da própria planta</translation>
    </message>
    <message>
        <source>Perturb the bodies</source>
        <translation>Perturbar os corpos</translation>
    </message>
    <message>
        <source>Remove the perturbation</source>
        <translation>Remover a perturbação</translation>
    </message>
    <message>
        <source>Change the perturbation: %1</source>
        <translation>Alterar a perturbação: %1</translation>
    </message>
    <message>
        <source>Change the feedback rate</source>
        <translation>Alterar a taxa de realimentação</translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::PinSet</name>
    <message>
        <source> (does not solve)</source>
        <translation> (sem solução)</translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::PlanTool</name>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>Track this plan</source>
        <translation>Seguir este plano</translation>
    </message>
    <message>
        <source>at rest</source>
        <translation>em repouso</translation>
    </message>
    <message>
        <source>pivoting</source>
        <translation>pivotando</translation>
    </message>
    <message>
        <source>straight line</source>
        <translation>linha reta</translation>
    </message>
    <message>
        <source>libration</source>
        <translation>libração</translation>
    </message>
    <message>
        <source>rotation</source>
        <translation>rotação</translation>
    </message>
    <message>
        <source>separatrix</source>
        <translation>separatriz</translation>
    </message>
    <message>
        <source>motion %1 of %2: %3, k = %4, Ψ₀ = %5 rad, λ(0) = %6 kg m/s, t = %7 s, cut time %8%9</source>
        <translation>movimento %1 de %2: %3, k = %4, Ψ₀ = %5 rad, λ(0) = %6 kg m/s, t = %7 s, tempo de corte %8%9</translation>
    </message>
    <message>
        <source>, optimal</source>
        <translation>, ótimo</translation>
    </message>
    <message>
        <source>Planning needs constant energy (v_T): the constant-speed mode has no genuine vakonomic motion</source>
        <translation>O planejamento requer energia constante (v_T): o modo de velocidade constante não tem movimento vakonômico genuíno</translation>
    </message>
    <message>
        <source>No motion reaches the target within %1 s</source>
        <translation>Nenhum movimento alcança o alvo em até %1 s</translation>
    </message>
    <message>
        <source>Choose a planned motion</source>
        <translation>Escolher um movimento planejado</translation>
    </message>
    <message>
        <source>Move the plan&apos;s start</source>
        <translation>Mover o início do plano</translation>
    </message>
    <message>
        <source>Move the plan&apos;s target</source>
        <translation>Mover o alvo do plano</translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::PlotCrosshair</name>
    <message>
        <source>t = %1 s</source>
        <translation>t = %1 s</translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::PlotsPanel</name>
    <message>
        <source> — click or drag to move the animation to that time; wheel: zoom the time, Shift+drag or middle drag: pan it, double click: the whole run</source>
        <translation> — clique ou arraste para levar a animação a esse instante; roda: zoom no tempo, Shift+arrastar ou arrastar com o botão do meio: deslocá-lo, clique duplo: a execução inteira</translation>
    </message>
    <message>
        <source>&amp;Follow the cursor</source>
        <translation>&amp;Seguir o cursor</translation>
    </message>
    <message>
        <source>The time plots show a window of the run that moves on with the time cursor</source>
        <translation>Os gráficos no tempo mostram uma janela da execução que avança com o cursor do tempo</translation>
    </message>
    <message>
        <source>&amp;Whole run</source>
        <translation>&amp;Execução inteira</translation>
    </message>
    <message>
        <source>The time plots show the whole run (a double click on a plot)</source>
        <translation>Os gráficos no tempo mostram a execução inteira (um clique duplo num gráfico)</translation>
    </message>
    <message>
        <source>Zoom &amp;in on the time</source>
        <translation>&amp;Aproximar o tempo</translation>
    </message>
    <message>
        <source>Zoom &amp;out the time</source>
        <translation>A&amp;fastar o tempo</translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::PresentationMode</name>
    <message>
        <source>&amp;Presentation mode</source>
        <translation>Modo de &amp;apresentação</translation>
    </message>
    <message>
        <source>Presentation mode: full screen, large fonts and lines, high contrast (F11; Esc leaves)</source>
        <translation>Modo de apresentação: tela cheia, fontes e linhas grandes, alto contraste (F11; Esc sai)</translation>
    </message>
    <message>
        <source>Leave presentation mode</source>
        <translation>Sair do modo de apresentação</translation>
    </message>
    <message>
        <source>Presentation &amp;scale</source>
        <translation>Esca&amp;la da apresentação</translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::SceneCanvas</name>
    <message>
        <source>controlled body and its trail (tracks the path)</source>
        <translation>corpo controlado e seu rastro (segue o caminho)</translation>
    </message>
    <message>
        <source>path (● start, □ end), coloured by its curvature κ: red right turn, grey straight, blue left turn</source>
        <translation>caminho (● início, □ fim), colorido pela sua curvatura κ: vermelho curva à direita, cinza reta, azul curva à esquerda</translation>
    </message>
    <message>
        <source>Draw mode: drag to draw a new path; drag a square to move a point, right-click it to delete it</source>
        <translation>Modo de desenho: arraste para desenhar um novo caminho; arraste um quadrado para mover um ponto, clique com o botão direito para excluí-lo</translation>
    </message>
    <message>
        <source>t = %1 s of %2 s    scale %3 px/m</source>
        <translation>t = %1 s de %2 s    escala %3 px/m</translation>
    </message>
    <message>
        <source>Scene canvas</source>
        <translation>Tela de desenho da cena</translation>
    </message>
    <message>
        <source>The animation: the prescribed path, the controlled body and the free motion from the same start</source>
        <translation>A animação: o caminho prescrito, o corpo controlado e o movimento livre a partir do mesmo início</translation>
    </message>
    <message>
        <source>free motion from the same start (ghost)</source>
        <translation>movimento livre a partir do mesmo início (fantasma)</translation>
    </message>
    <message>
        <source>genuine vakonomic body: λ obeys its own equation (21)</source>
        <translation>corpo vakonômico genuíno: λ obedece à sua própria equação (21)</translation>
    </message>
    <message>
        <source>path (● start, □ end)</source>
        <translation>caminho (● início, □ fim)</translation>
    </message>
    <message>
        <source>t = %1 s</source>
        <translation>t = %1 s</translation>
    </message>
    <message>
        <source>of %1 s</source>
        <translation>de %1 s</translation>
    </message>
    <message>
        <source>pushed, open loop: the nominal λ(t) as planned</source>
        <translation>empurrado, malha aberta: o λ(t) nominal como planejado</translation>
    </message>
    <message>
        <source>pushed, closed loop: feedback steers it back</source>
        <translation>empurrado, malha fechada: a realimentação o traz de volta</translation>
    </message>
    <message>
        <source>Wheel or +/-: zoom; drag or arrows: pan; F: fit the path; Shift+F: fit everything that moves; B: follow body; L: legend</source>
        <translation>Roda ou +/-: zoom; arrastar ou setas: deslocar; F: ajustar ao caminho; Shift+F: ajustar a tudo o que se move; B: seguir o corpo; L: legenda</translation>
    </message>
    <message>
        <source>controlled body (tracks the path)</source>
        <translation>corpo controlado (segue o caminho)</translation>
    </message>
    <message>
        <source>controlled body</source>
        <translation>corpo controlado</translation>
    </message>
    <message>
        <source>free motion (ghost)</source>
        <translation>movimento livre (fantasma)</translation>
    </message>
    <message>
        <source>pushed, open loop</source>
        <translation>empurrado, malha aberta</translation>
    </message>
    <message>
        <source>pushed, closed loop (feedback)</source>
        <translation>empurrado, malha fechada (realimentação)</translation>
    </message>
    <message>
        <source>vakonomic body, equation (21)</source>
        <translation>corpo vakonômico, equação (21)</translation>
    </message>
    <message>
        <source>curves drawn in part at this zoom</source>
        <translation>curvas desenhadas em parte neste zoom</translation>
    </message>
    <message>
        <source>Plan: drag the target&apos;s dot or its heading&apos;s handle (Shift snaps), or the start; click a motion to choose it</source>
        <translation>Plano: arraste o ponto do alvo ou a alça de sua direção (Shift ajusta à grade), ou o início; clique num movimento para escolhê-lo</translation>
    </message>
    <message>
        <source>a body too large to draw at this zoom</source>
        <translation>um corpo grande demais para desenhar neste zoom</translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::SceneDocument</name>
    <message>
        <source>internal error: %1</source>
        <translation>erro interno: %1</translation>
    </message>
    <message>
        <source>cannot save &apos;%1&apos;</source>
        <translation>não é possível salvar &apos;%1&apos;</translation>
    </message>
    <message>
        <source>the scene does not solve (%1); fix it or undo first</source>
        <translation>a cena não tem solução (%1); corrija-a ou desfaça antes</translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::SweepPanel</name>
    <message>
        <source>The parameter to vary; the others keep the scene&apos;s values</source>
        <translation>O parâmetro a variar; os demais mantêm os valores da cena</translation>
    </message>
    <message>
        <source>Run sweep</source>
        <translation>Executar varredura</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
    <message>
        <source>Choose a parameter and a range, then Run sweep. Click a point to load its value.</source>
        <translation>Escolha um parâmetro e um intervalo e clique em Executar varredura. Clique em um ponto para carregar o seu valor.</translation>
    </message>
    <message>
        <source>from</source>
        <translation>de</translation>
    </message>
    <message>
        <source>to</source>
        <translation>até</translation>
    </message>
    <message>
        <source>values</source>
        <translation>valores</translation>
    </message>
    <message>
        <source>Plot</source>
        <translation>Gráfico</translation>
    </message>
    <message>
        <source>Sweeping %1 over %2 values…</source>
        <translation>Varrendo %1 em %2 valores…</translation>
    </message>
    <message>
        <source>The sweep failed: %1</source>
        <translation>A varredura falhou: %1</translation>
    </message>
    <message>
        <source>1 value of %1 from %2 to %3</source>
        <translation>1 valor de %1 de %2 até %3</translation>
    </message>
    <message>
        <source>%1 values of %2 from %3 to %4</source>
        <translation>%1 valores de %2 de %3 até %4</translation>
    </message>
    <message>
        <source>%1. Click a point to load it.</source>
        <translation>%1. Clique em um ponto para carregá-lo.</translation>
    </message>
    <message>
        <source>Cancelled (the scene changed) after %1.</source>
        <translation>Cancelado (a cena mudou) após %1.</translation>
    </message>
    <message>
        <source>Cancelled after %1. Click a point to load it.</source>
        <translation>Cancelado após %1. Clique em um ponto para carregá-lo.</translation>
    </message>
    <message>
        <source>Set %1 = %2 from the sweep</source>
        <translation>Definir %1 = %2 a partir da varredura</translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::TimelineBar</name>
    <message>
        <source>Timeline</source>
        <translation>Linha do tempo</translation>
    </message>
    <message>
        <source>Step &amp;back</source>
        <translation>Passo para &amp;trás</translation>
    </message>
    <message>
        <source>&amp;Play</source>
        <translation>&amp;Reproduzir</translation>
    </message>
    <message>
        <source>Play or pause (Space)</source>
        <translation>Reproduzir ou pausar (Espaço)</translation>
    </message>
    <message>
        <source>Step &amp;forward</source>
        <translation>Passo para a &amp;frente</translation>
    </message>
    <message>
        <source>Loop</source>
        <translation>Repetir</translation>
    </message>
    <message>
        <source>Start again at the end</source>
        <translation>Recomeçar ao chegar ao fim</translation>
    </message>
    <message>
        <source>Scrub through time</source>
        <translation>Percorrer o tempo</translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation>&amp;Pausar</translation>
    </message>
    <message>
        <source> t = %1 s / %2 s</source>
        <translation> t = %1 s / %2 s</translation>
    </message>
    <message>
        <source>One frame back at the current speed (,); Shift+, one second</source>
        <translation>Um quadro para trás na velocidade atual (,); Shift+, um segundo</translation>
    </message>
    <message>
        <source>One frame forward at the current speed (.); Shift+. one second</source>
        <translation>Um quadro para a frente na velocidade atual (.); Shift+. um segundo</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Tempo</translation>
    </message>
    <message>
        <source>The animation time; arrows and Page Up/Down scrub</source>
        <translation>O tempo da animação; as setas e Page Up/Down o percorrem</translation>
    </message>
    <message>
        <source>Time read-out</source>
        <translation>Leitura do tempo</translation>
    </message>
    <message>
        <source>Go to the &amp;start</source>
        <translation>Ir para o &amp;início</translation>
    </message>
    <message>
        <source>Go to the &amp;end</source>
        <translation>Ir para o fi&amp;m</translation>
    </message>
    <message>
        <source>One second back</source>
        <translation>Um segundo para trás</translation>
    </message>
    <message>
        <source>One second forward</source>
        <translation>Um segundo para a frente</translation>
    </message>
    <message>
        <source>Playback speed: simulated seconds per real second ([ slower, ] faster)</source>
        <translation>Velocidade de reprodução: segundos simulados por segundo real ([ mais lento, ] mais rápido)</translation>
    </message>
    <message>
        <source>&amp;Faster</source>
        <translation>&amp;Mais rápido</translation>
    </message>
    <message>
        <source>&amp;Slower</source>
        <translation>Mais &amp;lento</translation>
    </message>
    <message>
        <source>&amp;Normal speed (×%1)</source>
        <translation>Velocidade &amp;normal (×%1)</translation>
    </message>
    <message>
        <source>Spee&amp;d</source>
        <translation>&amp;Velocidade</translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::ValuesPanel</name>
    <message>
        <source>&amp;Copy</source>
        <translation>&amp;Copiar</translation>
    </message>
    <message>
        <source>Column</source>
        <translation>Coluna</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Valor</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Unidade</translation>
    </message>
    <message>
        <source>Values at the shown time</source>
        <translation>Valores no instante mostrado</translation>
    </message>
    <message>
        <source>Copy the values as tab-separated lines (column, value, unit)</source>
        <translation>Copia os valores como linhas separadas por tabulação (coluna, valor, unidade)</translation>
    </message>
</context>
<context>
    <name>chaplygin::ui::VectorsMenu</name>
    <message>
        <source>&amp;Vectors</source>
        <translation>&amp;Vetores</translation>
    </message>
    <message>
        <source>Show %1</source>
        <translation>Mostrar %1</translation>
    </message>
    <message>
        <source>Hide %1</source>
        <translation>Ocultar %1</translation>
    </message>
    <message>
        <source>&amp;Longer arrows</source>
        <translation>Setas mais &amp;longas</translation>
    </message>
    <message>
        <source>&amp;Shorter arrows</source>
        <translation>Setas mais &amp;curtas</translation>
    </message>
    <message>
        <source>&amp;Automatic lengths</source>
        <translation>Comprimentos &amp;automáticos</translation>
    </message>
    <message>
        <source>Automatic arrow lengths</source>
        <translation>Comprimentos automáticos das setas</translation>
    </message>
    <message>
        <source>Arrow lengths ×%1</source>
        <translation>Comprimentos das setas ×%1</translation>
    </message>
</context>
</TS>
